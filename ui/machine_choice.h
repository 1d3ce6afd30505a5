#pragma once
// File > Machine...: the operator switches to another of the cell's machines without leaving
// the program (issue 19, one frame). The window that asks stops its own machine first, and asks
// before that when something moves; main() then opens the chosen machine's screen.
#include <QString>
#include <optional>

#include "core/profile/machine_kind.h"

class QWidget;

namespace trilho {
namespace ui {

/// The shipped profile's name of a machine (rail, xy_dc_table, xy_plotter).
QString shippedProfileName(MachineKind kind);
/// The machine's name on screen, in the UI language (as the start screen names it).
QString machineName(MachineKind kind);
/// Asks which machine; nullopt when cancelled or the current one was chosen.
std::optional<MachineKind> chooseMachine(QWidget* parent, MachineKind current);
/// "The rail moves: switching stops it first." question, or empty when nothing moves.
QString switchQuestion(MachineKind current, MachineKind next);

}  // namespace ui
}  // namespace trilho
