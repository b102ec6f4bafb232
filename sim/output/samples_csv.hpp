// `cncsim run --samples FILE`: the carriage's tool samples as a CSV a spreadsheet, numpy or gnuplot loads
// (docs/usage.md, "Output files"): a header line `t_s,x_mm,y_mm`, then one row per sample in time order.
#pragma once
#include <ostream>
#include <vector>

#include "common/tool_sample.hpp"

namespace cnc::sim {

inline constexpr const char* kSamplesCsvHeader = "t_s,x_mm,y_mm";

// Times to the picosecond (12 decimals: the simulation's resolution), positions to the picometre (9 decimals of a mm:
// a microstep is micrometres, the dynamic mechanics move by less between samples).
void write_samples_csv(std::ostream& out, const std::vector<ToolSample>& samples);

}  // namespace cnc::sim
