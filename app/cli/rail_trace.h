#pragma once
// The rail's `trilho-cli run --trace` CSV: its header and one row per servo tick, formatted
// with std::to_chars (CsvRow). The bytes are those of the former
// "%.4f,%d,%.4f,%.4f,%.4f,%.3f,%d" row, but for the position and the error with 6 decimals (a
// count on the rail is 0.0438596 mm; 4 decimals put one count off outside the one-count band
// of `tune metrics`).
#include "core/runtime/servo_worker.h"
#include "core/tuning/trace_writer.h"

namespace trilho::cli {

inline constexpr const char* kRailTraceHeader =
    "t_s,block_n,setpoint_mm,position_mm,error_mm,velocity_mm_s,drive\n";

/// Row r, with its newline, into row (cleared first).
void formatRailTraceRow(const TraceRow& r, CsvRow& row);

}  // namespace trilho::cli
