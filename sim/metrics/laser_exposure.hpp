// Laser exposure per mm of path: how long the beam dwells on each stretch of the path the tool actually
// followed. Where the head slows down, stops or rings, a stretch gets more time than the feed gives it
// (over-burn); a head that ideally moves at a constant feed F gives every stretch 60 / F s per mm.
#pragma once
#include <vector>

#include "common/edge_log.hpp"
#include "common/tool_sample.hpp"

namespace cnc::metrics {

struct LaserExposure {
    double lasered_path_mm = 0.0;   // path length the tool covered with the laser on
    double on_time_s = 0.0;         // laser on-time over that path (including time spent standing still)
    double mean_s_per_mm = 0.0;     // on_time / path
    double peak_s_per_mm = 0.0;     // the worst bin of kExposureBinMm along the lasered path
    double peak_at_path_mm = 0.0;   // where that bin starts, mm of lasered path from the first
};

inline constexpr double kExposureBinMm = 0.5;

// Between consecutive tool samples the tool is taken to move in a straight line at constant speed, and the
// laser's on-time in that interval is spread over the distance covered.
[[nodiscard]] LaserExposure laser_exposure(const std::vector<ToolSample>& tool, const EdgeLog& laser);

}  // namespace cnc::metrics
