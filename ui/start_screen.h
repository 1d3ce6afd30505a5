#pragma once
// Tela inicial (screens.md 1): the title panel crediting the 1996 design; OK opens the main
// screen of the machine chosen below it (the rail, the DC XY table or the XY plotter).
#include <QDialog>

#include "core/profile/machine_kind.h"

class QComboBox;

class QLabel;
class QPushButton;

namespace trilho {
namespace ui {

class StartScreen : public QDialog {
    Q_OBJECT
  public:
    explicit StartScreen(QWidget* parent = nullptr);
    QPushButton* okButton() const { return ok_; }
    QComboBox* machineBox() const { return machine_; }
    void setMachine(MachineKind kind);
    MachineKind machine() const;

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QPushButton* ok_;
    QLabel *university_, *school_, *title_, *authors_, *credit_, *machineLabel_;
    QComboBox* machine_;
};

}  // namespace ui
}  // namespace trilho
