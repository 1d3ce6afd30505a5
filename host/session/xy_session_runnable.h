#pragma once
// The XY sessions of host/session (controller and simulated plant) as the screens' link runs
// them.
#include <memory>

#include "host/session/xy_device_session.h"
#include "host/session/xy_link.h"
#include "host/session/xy_session.h"

namespace trilho {

class XySessionRunnable : public XyRunnable {
  public:
    explicit XySessionRunnable(std::unique_ptr<XySession> session) : session_(std::move(session)) {}
    void step(double dtS) override { session_->step(dtS); }
    XyController& controller() override { return session_->controller(); }
    double periodS() const override { return session_->periodS(); }
    XyPlant* plant() override { return session_->hasPlant() ? &session_->plant() : nullptr; }

  private:
    std::unique_ptr<XySession> session_;
};

/// A board on a serial line: the session and the line it owns (drive it with
/// XyLink::Drive::EventLoop, where the line's bytes arrive).
class XyDeviceRunnable : public XyRunnable {
  public:
    explicit XyDeviceRunnable(XyDeviceSession device) : device_(std::move(device)) {}
    void step(double dtS) override { device_.session->step(dtS); }
    XyController& controller() override { return device_.session->controller(); }
    double periodS() const override { return device_.session->periodS(); }
    SerialLinkMotion* link() const { return device_.link; }

  private:
    XyDeviceSession device_;
};

}  // namespace trilho
