// libFuzzer target: the machine profile reader (machineProfileFromJson) on any bytes. A profile
// it accepts must print and read back as the same accepted profile, and print the same again
// (its notes kept); it never accepts text that gives a key twice in one object (issue 20 item
// 14), and what it prints never does.
#include <cstdint>

#include "core/profile/json_duplicate_keys.h"
#include "core/profile/machine_profile.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    fuzz::ensureApplication();
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const ProfileLoad load = machineProfileFromJson(json, QStringLiteral("fuzz.json"));
    FUZZ_CHECK(load.profile.has_value() == load.error.isEmpty());
    if (load.profile) {
        FUZZ_CHECK(!findDuplicateKey(json).has_value());
        const QByteArray printed = machineProfileToJson(*load.profile);
        FUZZ_CHECK(!findDuplicateKey(printed).has_value());
        const ProfileLoad again = machineProfileFromJson(printed, QStringLiteral("again"));
        FUZZ_CHECK(again.profile.has_value());
        // Printed with its notes (issue 30 item 12), it prints again the same, and reads back
        // as the same profile.
        FUZZ_CHECK(machineProfileToJson(*again.profile) == printed);
        MachineProfile read = *load.profile, reread = *again.profile;
        read.origin = reread.origin = {};
        FUZZ_CHECK(machineProfileToJson(read) == machineProfileToJson(reread));
    }
    return 0;
}
