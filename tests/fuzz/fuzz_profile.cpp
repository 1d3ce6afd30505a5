// libFuzzer target: the machine profile reader (machineProfileFromJson) on any bytes. A profile
// it accepts must print and read back as the same accepted profile.
#include <cstdint>

#include "core/machine/machine_profile.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const ProfileLoad load = machineProfileFromJson(json, QStringLiteral("fuzz.json"));
    FUZZ_CHECK(load.profile.has_value() == load.error.isEmpty());
    if (load.profile) {
        const ProfileLoad again =
            machineProfileFromJson(machineProfileToJson(*load.profile), QStringLiteral("again"));
        FUZZ_CHECK(again.profile.has_value());
    }
    return 0;
}
