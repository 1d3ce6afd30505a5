#pragma once
// The question every screen asks before a motion the operator did not type (issue 19 item 2):
// Yes/No, No by default, so a stray Enter never starts a machine.
#include <QMessageBox>

namespace trilho::ui {

/// details: the box's "Show Details..." text (the Cycle start question's pre-run check), none
/// when empty.
inline bool askYesNoDefaultNo(QWidget* parent, const QString& title, const QString& text,
                              const QString& details = {}) {
    QMessageBox box(QMessageBox::Question, title, text, QMessageBox::Yes | QMessageBox::No, parent);
    box.setObjectName(QStringLiteral("confirmation"));
    if (!details.isEmpty()) box.setDetailedText(details);
    box.setDefaultButton(QMessageBox::No);
    return box.exec() == QMessageBox::Yes;
}

}  // namespace trilho::ui
