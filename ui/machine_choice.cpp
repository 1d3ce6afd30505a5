#include "ui/machine_choice.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QStringList>

namespace trilho {
namespace ui {

namespace {
constexpr MachineKind kMachines[] = {MachineKind::Rail, MachineKind::DcTable, MachineKind::Plotter};
}  // namespace

QString shippedProfileName(MachineKind kind) {
    switch (kind) {
        case MachineKind::DcTable:
            return QStringLiteral("xy_dc_table");
        case MachineKind::Plotter:
            return QStringLiteral("xy_plotter");
        case MachineKind::Rail:
            break;
    }
    return QStringLiteral("rail");
}

QString machineName(MachineKind kind) {
    switch (kind) {
        case MachineKind::DcTable:
            return QCoreApplication::translate("trilho::ui::MachineChoice", "DC-motor XY table");
        case MachineKind::Plotter:
            return QCoreApplication::translate("trilho::ui::MachineChoice", "Stepper XY plotter");
        case MachineKind::Rail:
            break;
    }
    return QCoreApplication::translate("trilho::ui::MachineChoice", "Robot rail (1996)");
}

std::optional<MachineKind> chooseMachine(QWidget* parent, MachineKind current) {
    QStringList names;
    int at = 0;
    for (MachineKind k : kMachines) {
        if (k == current) at = static_cast<int>(names.size());
        names << machineName(k);
    }
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        parent, QCoreApplication::translate("trilho::ui::MachineChoice", "Machine"),
        QCoreApplication::translate("trilho::ui::MachineChoice", "&Machine:"), names, at, false,
        &ok);
    if (!ok) return std::nullopt;
    const auto index = names.indexOf(chosen);
    if (index < 0 || kMachines[index] == current) return std::nullopt;
    return kMachines[index];
}

QString switchQuestion(MachineKind current, MachineKind next) {
    return QCoreApplication::translate(
               "trilho::ui::MachineChoice",
               "%1 is moving. Switching to %2 stops it first (a controlled stop) and "
               "closes its screen. Switch?")
        .arg(machineName(current), machineName(next));
}

}  // namespace ui
}  // namespace trilho
