#pragma once
// The XY machines' `trilho-cli run --trace` CSV: its header, the raw numbers of one period
// (what the run's thread copies, plain numbers only) and their row, formatted with
// std::to_chars (CsvRow): the columns and decimals of the former
// "%.4f,%d,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%s", the positions with 6 decimals (a count within
// `tune metrics`' one-count band).
#include <cstdint>

#include "core/tuning/trace_writer.h"
#include "core/xy/xy_controller.h"

namespace trilho::cli {

/// pen: 1 down, 0 up, empty on the DC table (which has none).
inline constexpr const char* kXyTraceHeader =
    "t_s,block_n,x_setpoint_mm,x_position_mm,y_setpoint_mm,y_position_mm,x_drive,y_drive,pen\n";

struct XyTraceRow {
    double timeS;
    std::int32_t blockN;
    double xSetpointMm, xPositionMm, ySetpointMm, yPositionMm;
    double xDrive, yDrive;  ///< PWM %, signed (DC table); step rate, steps/s (plotter)
    PenState pen;
};

XyTraceRow xyTraceRow(const XyStatus& s);

/// Row r, with its newline, into row (cleared first).
void formatXyTraceRow(const XyTraceRow& r, CsvRow& row);

}  // namespace trilho::cli
