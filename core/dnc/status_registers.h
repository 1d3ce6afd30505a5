#pragma once
// The input registers (and the live holding registers: gains, feed override) from a status
// snapshot and what the link itself keeps. Plain and deterministic: the server calls it on a
// timer and before each read; the tests check the encoding against register_map.h.
#include <array>
#include <cstdint>
#include <optional>

#include "core/dnc/register_map.h"
#include "core/dnc/y_axis_readout.h"
#include "core/profile/machine_kind.h"
#include "core/rail/rail_controller.h"

namespace trilho::dnc {

/// What the link knows that the controller does not.
struct LinkState {
    std::uint16_t program = 0;     ///< number of the program started over the link
    std::uint16_t alarmSeq = 0;    ///< alarms and warnings raised so far (wraps)
    std::uint16_t commandSeq = 0;  ///< seq of the last command applied or refused
    CommandResult commandResult = CommandResult::None;
    bool remote = false;           ///< the operator's consent to remote writes
    std::uint16_t diagErrors = 0;  ///< of the last compile over the link
    std::uint16_t diagCode = 0;    ///< MessageId + 1 of its first error
    std::uint16_t diagLine = 0;
    std::uint16_t diagProgram = 0;
};

using InputImage = std::array<std::uint16_t, in::kCount>;
using HoldingImage = std::array<std::uint16_t, hold::kCount>;

/// machine: in::kMachine's value (MachineKind); y: none on the rail (its Y registers NaN).
void fillInputRegisters(const ControllerStatus& s, const LinkState& link, InputImage& out,
                        MachineKind machine = MachineKind::Rail,
                        const std::optional<YAxisReadout>& y = std::nullopt);
/// Gains of the active law and the feed override, as the controller has them now.
void fillLiveHolding(const ControllerStatus& s, HoldingImage& out);

}  // namespace trilho::dnc
