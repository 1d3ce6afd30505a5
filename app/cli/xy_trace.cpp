#include "app/cli/xy_trace.h"

namespace trilho::cli {

XyTraceRow xyTraceRow(const XyStatus& s) {
    return {s.timeS,
            s.blockN,
            s.sample.x.setpointMm,
            s.sample.x.positionMm,
            s.sample.y.setpointMm,
            s.sample.y.positionMm,
            s.sample.x.drive,
            s.sample.y.drive,
            s.sample.pen};
}

void formatXyTraceRow(const XyTraceRow& r, CsvRow& row) {
    row.clear();
    row.num(r.timeS, 4)
        .integer(r.blockN)
        .num(r.xSetpointMm, 4)
        .num(r.xPositionMm, 6)
        .num(r.ySetpointMm, 4)
        .num(r.yPositionMm, 6)
        .num(r.xDrive, 3)
        .num(r.yDrive, 3);
    if (r.pen == PenState::Down)
        row.integer(1);
    else if (r.pen == PenState::Up)
        row.integer(0);
    else
        row.empty();
    row.end();
}

}  // namespace trilho::cli
