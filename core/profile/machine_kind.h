#pragma once
// Which machine a profile describes: the rail of machine.md or one of the two XY tables of
// xy.md. The kind decides which sections a profile may hold and which controller runs it.
#include <optional>
#include <string_view>

namespace trilho {

enum class MachineKind : unsigned char {
    Rail,     ///< machine.md: DC servo, DAC and counter, one axis ("rail")
    DcTable,  ///< xy.md B, seed 004: two DC axes, PWM and encoders ("xy-dc-table")
    Plotter,  ///< xy.md A, seed 001: two steppers and a pen ("xy-plotter")
};

constexpr std::string_view machineKindName(MachineKind k) {
    switch (k) {
        case MachineKind::Rail:
            return "rail";
        case MachineKind::DcTable:
            return "xy-dc-table";
        case MachineKind::Plotter:
            return "xy-plotter";
    }
    return "rail";
}

constexpr std::optional<MachineKind> machineKindFromName(std::string_view name) {
    for (MachineKind k : {MachineKind::Rail, MachineKind::DcTable, MachineKind::Plotter})
        if (machineKindName(k) == name) return k;
    return std::nullopt;
}

}  // namespace trilho
