#include "app/cli/rail_trace.h"

namespace trilho::cli {

void formatRailTraceRow(const TraceRow& r, CsvRow& row) {
    row.clear();
    row.num(r.timeS, 4)
        .integer(r.blockN)
        .num(r.setpointMm, 4)
        .num(r.positionMm, 6)
        .num(r.errorMm, 6)
        .num(r.velocityMmS, 3)
        .integer(r.drive)
        .end();
}

}  // namespace trilho::cli
