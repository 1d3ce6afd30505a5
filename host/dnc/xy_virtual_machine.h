#pragma once
// An XY machine (the DC table or the plotter) behind the DNC server, in virtual time, stepped
// by the event loop as VirtualMachine steps the rail (issue 19, one frame: the same Modbus
// link on every machine). The server sees the rail's status with the x axis in the rail's
// position registers and the Y axis in its own (register_map.h); the commands map onto the XY
// controller's. Gains and the control law are the rail's: their writes are refused here.
#include <QObject>
#include <QTimer>
#include <memory>

#include "host/dnc/dnc_machine.h"
#include "host/session/xy_session.h"

namespace trilho::dnc {

/// An XY machine's status as the rail's registers read it: x in the rail's position fields.
ControllerStatus asRailStatus(const XyStatus& x);
YAxisReadout yAxisOf(const XyStatus& x);
/// Whether an XY controller takes a command of the link (not the rail's own: manual drive
/// codes, jogs, gains, the law, a program handed over).
bool xyTakes(CommandKind kind);
/// Applies a command xyTakes() on the XY controller, as the screens' buttons do.
void applyXyCommand(XyController& c, CommandKind kind, std::int64_t i, double a);

class XyVirtualMachine final : public QObject, public DncMachine {
    Q_OBJECT
  public:
    /// periodsPerTick loop periods each millisecond of the event loop (0: no timer, tests
    /// call tick()).
    XyVirtualMachine(const MachineProfile& profile, int periodsPerTick, std::uint64_t seed = 1,
                     QObject* parent = nullptr);

    ControllerStatus snapshot() const override;
    Ticket send(CommandKind kind, std::int64_t i, double a, double b, double c) override;
    Ticket loadProgram(std::shared_ptr<const Program> program) override;
    Ticket requestStop() override;
    bool applied(const Ticket&) const override { return true; }
    void drainEvents(const std::function<void(const ControllerEvent&)>& f) override {
        session_->controller().drainEvents(f);
    }
    const MachineProfile& profile() const override { return profile_; }
    std::optional<YAxisReadout> yAxis() const override;

    /// One tick: periodsPerTick loop periods (one when the timer is off).
    void tick();
    XyController& controller() { return session_->controller(); }
    double periodS() const { return session_->periodS(); }

  private:
    MachineProfile profile_;
    std::unique_ptr<XySession> session_;
    QTimer timer_;
    int periodsPerTick_;
    std::uint64_t seq_ = 0;
};

}  // namespace trilho::dnc
