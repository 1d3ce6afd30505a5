#pragma once
// The run controls a shift needs on the main screen in both modes (issue 10): cycle start,
// feed hold, continue, stop, single block and feed override, each an action with a key so the
// Help > Keys page and the buttons can never disagree. It raises intents; the main window
// decides (and asks) what they do.
#include <QElapsedTimer>
#include <QList>
#include <QWidget>

#include "core/rail/rail_controller.h"

class QAction;
class QLabel;
class QSlider;
class QToolButton;

namespace trilho {
namespace ui {

class RunControls : public QWidget {
    Q_OBJECT
  public:
    explicit RunControls(QWidget* parent = nullptr);

    /// Enables each control as the controller's state allows (greyed otherwise).
    void showStatus(const ControllerStatus& s, bool programSelected, bool compiling);

    QAction* cycleStartAction() const { return start_; }
    QAction* holdAction() const { return hold_; }
    QAction* continueAction() const { return continue_; }
    QAction* stopAction() const { return stop_; }
    QAction* singleBlockAction() const { return single_; }
    QAction* overrideUpAction() const { return overrideUp_; }
    QAction* overrideDownAction() const { return overrideDown_; }
    QAction* overrideResetAction() const { return overrideReset_; }
    /// Every action with its key, in screen order (the Keys page lists them).
    QList<QAction*> keyedActions() const;
    QSlider* overrideSlider() const { return override_; }
    QToolButton* buttonFor(QAction* action) const;

  signals:
    void cycleStartRequested();
    void holdRequested();
    void continueRequested();
    void stopRequested();
    void singleBlockToggled(bool on);
    void feedOverrideChanged(double factor);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QAction *start_, *hold_, *continue_, *stop_, *single_, *overrideUp_, *overrideDown_,
        *overrideReset_;
    QList<QToolButton*> buttons_;
    QSlider* override_;
    QElapsedTimer overrideSent_;  ///< since the operator last moved the override
    QLabel* overrideLabel_;
};

}  // namespace ui
}  // namespace trilho
