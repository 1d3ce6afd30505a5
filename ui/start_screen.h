#pragma once
// Tela inicial (screens.md 1): the title panel crediting the 1996 design; OK opens the main
// screen.
#include <QDialog>

class QLabel;
class QPushButton;

namespace trilho {
namespace ui {

class StartScreen : public QDialog {
    Q_OBJECT
  public:
    explicit StartScreen(QWidget* parent = nullptr);
    QPushButton* okButton() const { return ok_; }

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QPushButton* ok_;
    QLabel *university_, *school_, *title_, *authors_, *credit_;
};

}  // namespace ui
}  // namespace trilho
