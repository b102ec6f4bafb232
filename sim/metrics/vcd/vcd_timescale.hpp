// VCD $timescale values and the conversion of VCD times to and from integer picoseconds, shared by the reader,
// the writer and the trace.timescale key. A timescale is held in femtoseconds (100 s = 1e17 fs fits int64).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/units.hpp"

namespace cnc::metrics {

// "1ps", "10 ns" (white space anywhere), "100us", "1 s", "10 fs": 1, 10 or 100 of s/ms/us/ns/ps/fs.
[[nodiscard]] std::optional<std::int64_t> parse_vcd_timescale_fs(const std::string& text);
// The inverse: "10 ns" for 10'000'000 fs; nullopt if `timescale_fs` is not such a value.
[[nodiscard]] std::optional<std::string> format_vcd_timescale(std::int64_t timescale_fs);
// Every value the standard allows, coarsest first ("100 s" .. "1 fs").
[[nodiscard]] std::vector<std::string> vcd_timescale_names();

// `units` ticks of the timescale in ps; a sub-picosecond timescale rounds to the nearest ps (half up), since
// times are integer ps everywhere else. nullopt when the result does not fit TimePs.
[[nodiscard]] std::optional<TimePs> vcd_ticks_to_ps(std::int64_t units, std::int64_t timescale_fs);
// `t_ps` (>= 0) in ticks of the timescale, rounded to the nearest tick (half up); std::overflow_error when a
// sub-picosecond timescale takes it past 64 bits (2.5 hours at 1 fs).
[[nodiscard]] std::int64_t ps_to_vcd_ticks(TimePs t_ps, std::int64_t timescale_fs);
// Whether `t_ps` is a whole number of ticks (always, for a timescale of 1 ps or finer).
[[nodiscard]] bool on_vcd_tick(TimePs t_ps, std::int64_t timescale_fs);

}  // namespace cnc::metrics
