// VCD $timescale text <-> picoseconds, shared by the reader and the writer.
#pragma once
#include <optional>
#include <string>

#include "common/units.hpp"

namespace cnc::metrics {

// "1ps", "10 ns" (spaces removed by the caller or not), "100us", "1 s": 1, 10 or 100 of s/ms/us/ns/ps.
[[nodiscard]] std::optional<TimePs> parse_vcd_timescale(const std::string& text);
// The inverse: "10 ns" for 10'000; nullopt if `ps` is not such a value.
[[nodiscard]] std::optional<std::string> format_vcd_timescale(TimePs ps);

}  // namespace cnc::metrics
