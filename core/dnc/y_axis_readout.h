#pragma once
// The Y axis of an XY machine as the DNC link reports it (register_map.h, in::kYPosition to
// in::kYSpeed). Its own header: the machines behind the server name it without the register
// map (whose dnc::Command would hide the controller's trilho::Command there).

namespace trilho::dnc {

struct YAxisReadout {
    double positionMm = 0.0, setpointMm = 0.0, velocityMmS = 0.0;
};

}  // namespace trilho::dnc
