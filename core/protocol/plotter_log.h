#pragma once
// One line of the plotter's communication log, as seed 001's Java host printed it (figure 48):
// a packet sent, or the byte that answered it, with the time; the answer that ends an object
// (DONE) carries the object's total time, from its first packet sent to that answer.
#include <cstdint>
#include <functional>

#include "core/protocol/plotter_protocol.h"

namespace trilho {

struct PlotterLogEntry {
    double timeS = 0.0;                ///< the host's clock, s
    bool sent = true;                  ///< a packet to the board; false: a byte from it
    plotter_wire::Packet packet{};     ///< sent: the six bytes
    std::uint8_t answer = 0;           ///< received: the byte
    std::uint8_t answeredCommand = 0;  ///< received: the command in flight (0 none)
    int object = -1;                   ///< the object the packet belongs to (-1: none)
    bool objectStart = false;          ///< sent: the first packet of its object
    bool objectEnd = false;            ///< received: the DONE that ends an object
    double objectSeconds = 0.0;        ///< objectEnd: from its first packet to DONE, s
};

using PlotterMonitor = std::function<void(const PlotterLogEntry&)>;

}  // namespace trilho
