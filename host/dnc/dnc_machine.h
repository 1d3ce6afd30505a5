#pragma once
// The machine behind the DNC server: the rail's controller in real time (a ServoWorker) or in
// virtual time (a SimSession stepped by the event loop, for tests), or an XY machine in virtual
// time (XyVirtualMachine), which it shows with the rail's registers and its Y axis after them. The
// server only reads snapshots, sends commands and waits for their tickets; it never steps anything
// itself.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "core/dnc/y_axis_readout.h"
#include "core/gcode/program.h"
#include "core/rail/rail_controller.h"
#include "core/runtime/servo_worker.h"

namespace trilho::dnc {

/// Says when a command has been applied by the controller.
struct Ticket {
    bool byVersion = false;  ///< a flag (Stop): applied once the snapshot passed this version
    std::uint64_t value = 0;
    /// The machine did not take the command (its queue was full, or a program handed over is
    /// still waiting): nothing was queued and nothing will happen.
    bool refused = false;
};

/// The ticket of a command queued on a ServoWorker: its number, or refused (0).
inline Ticket workerTicket(std::uint64_t seq) {
    return {false, seq, seq == 0};
}

class DncMachine {
  public:
    virtual ~DncMachine() = default;
    virtual ControllerStatus snapshot() const = 0;
    /// A client's command: applied later (applied() says when), or refused at once.
    virtual Ticket send(CommandKind kind, std::int64_t i = 0, double a = 0.0, double b = 0.0,
                        double c = 0.0) = 0;
    virtual Ticket loadProgram(std::shared_ptr<const Program> program) = 0;
    /// Stop bypasses the queue (as the screens' Stop does).
    virtual Ticket requestStop() = 0;
    virtual bool applied(const Ticket& t) const = 0;
    virtual void drainEvents(const std::function<void(const ControllerEvent&)>& f) = 0;
    virtual const MachineProfile& profile() const = 0;
    /// The Y axis of an XY machine (input registers 36-43); none on the rail.
    virtual std::optional<YAxisReadout> yAxis() const { return std::nullopt; }
};

}  // namespace trilho::dnc
