#pragma once
// An XY controller driving a real board (or trilho-device's emulator) on a serial line: the
// controller's motion speaks the board's protocol (core/protocol) and the bytes go through
// hal/serial's SerialLine (Qt SerialPort). The session has no simulated plant; it needs a
// running Qt event loop (or processEvents) for the line's bytes to arrive.
#include <QString>
#include <memory>

#include "hal/serial/serial_line.h"
#include "host/session/xy_session.h"

namespace trilho {

class SerialLinkMotion;

struct XyDeviceSession {
    std::unique_ptr<XySession> session;
    std::unique_ptr<SerialLine> line;
    SerialLinkMotion* link = nullptr;  ///< the motion inside the controller (its link's state)
    QString error;                     ///< why there is none
};

/// Opens the port at settings.baud (0: the board's own rate: 57600 for the plotter, 9600 for
/// the DC table) and builds the controller over it.
XyDeviceSession makeXyDeviceSession(const MachineProfile& profile, SerialSettings settings);

}  // namespace trilho
