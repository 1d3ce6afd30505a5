#pragma once
// The digital readout an operator reads from across the cell (issue 10): the position in large
// digits, the program (work) coordinate beside the machine one while a g92 zero is active, the
// distance to go, the modal state, the cycle time, a dwell's countdown and the block progress.
// It only shows a controller snapshot; the cycle clock is the one thing it keeps.
#include <QWidget>

#include "core/rail/rail_controller.h"

class QLabel;
class QProgressBar;

namespace trilho {
namespace ui {

class DroPanel : public QWidget {
    Q_OBJECT
  public:
    explicit DroPanel(QWidget* parent = nullptr);
    void showStatus(const ControllerStatus& s);
    /// Blocks in the program being run (0: none), for "block 3 / 12".
    void setProgramBlocks(int blocks);

    QLabel* machinePosition() const { return machine_; }
    QLabel* workPosition() const { return work_; }
    QLabel* distanceToGo() const { return toGo_; }
    QLabel* modalState() const { return modal_; }
    QLabel* cycleTime() const { return cycle_; }
    QLabel* dwell() const { return dwell_; }
    QProgressBar* blockProgress() const { return progress_; }

  protected:
    void changeEvent(QEvent* e) override;
    void paintEvent(QPaintEvent* e) override;  ///< lets the style sheet paint the background

  private:
    void retranslate();
    QLabel *machineCaption_, *workCaption_, *toGoCaption_;
    QLabel *machine_, *work_, *toGo_, *modal_, *cycle_, *dwell_;
    QProgressBar* progress_;
    ControllerStatus last_;
    int blocks_ = 0;
    double cycleStartS_ = -1.0;  ///< controller time the running program started, -1 idle
    double cycleS_ = 0.0;        ///< the last cycle's length, kept after it ends
};

}  // namespace ui
}  // namespace trilho
