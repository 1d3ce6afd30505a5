#pragma once
// The XY sessions of app/session (controller and simulated plant) as the screens' link runs
// them.
#include <memory>

#include "app/session/xy_session.h"
#include "ui/xy/xy_link.h"

namespace trilho {
namespace ui {

class XySessionRunnable : public XyRunnable {
  public:
    explicit XySessionRunnable(std::unique_ptr<XySession> session) : session_(std::move(session)) {}
    void step(double dtS) override { session_->step(dtS); }
    XyController& controller() override { return session_->controller(); }
    double periodS() const override { return session_->periodS(); }

  private:
    std::unique_ptr<XySession> session_;
};

}  // namespace ui
}  // namespace trilho
