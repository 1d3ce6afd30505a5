#pragma once
// The rail drawn to scale: the track between its hard stops, the three switches, the soft
// limits, the platform where the counter says it is, and the target of the move.
#include <QWidget>

#include "core/profile/machine_profile.h"

namespace trilho {
namespace ui {

class RailView : public QWidget {
    Q_OBJECT
  public:
    explicit RailView(const MachineProfile& profile, QWidget* parent = nullptr);
    void setState(double positionMm, double targetMm, std::uint8_t switches, bool moving);
    QSize sizeHint() const override { return {600, 80}; }
    QSize minimumSizeHint() const override { return {240, 70}; }

  protected:
    void paintEvent(QPaintEvent*) override;

  private:
    double toX(double mm) const;
    MachineProfile profile_;
    double position_ = 0.0, target_ = 0.0;
    std::uint8_t switches_ = 248;
    bool moving_ = false;
};

}  // namespace ui
}  // namespace trilho
