#pragma once
// One tick of an XY machine whose board is across a serial line, in virtual time: the host's
// XyController over its SerialLinkMotion, a virtual line each way, and the board's emulated
// firmware (TableFirmware, PlotterFirmware). The order is the program's: the controller steps
// and sends, the board takes what arrived by then and steps, its answers go back up.
#include <cstdint>
#include <utility>

#include "core/xy/serial_link_motion.h"
#include "core/xy/xy_controller.h"
#include "tests/support/virtual_serial_line.h"

namespace trilho::test {

/// Advances t by dtS (s) and runs that tick; each event the controller raised goes to onEvent.
/// t is the clock the link motion's send callback stamps its bytes with.
template <typename Firmware, typename OnEvent>
void stepOverWire(XyController& c, SerialLinkMotion& link, Firmware& device, VirtualWire& down,
                  VirtualWire& up, double& t, double dtS, OnEvent&& onEvent) {
    t += dtS;
    c.step(dtS);
    down.deliver(t, [&](std::uint8_t b, double at) { device.receive(b, at); });
    device.step(dtS, t);
    up.send(device.takeOutput(), t);
    up.deliver(t, [&](std::uint8_t b, double) { link.onBytes(&b, 1); });
    c.drainEvents(std::forward<OnEvent>(onEvent));
}

}  // namespace trilho::test
