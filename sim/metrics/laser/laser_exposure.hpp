// Laser exposure per mm of path: how long the beam dwells on each stretch of the path the tool actually
// followed. Where the head slows down, stops or rings, a stretch gets more time than the feed gives it
// (over-burn); a head that ideally moves at a constant feed F gives every stretch 60 / F s per mm.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "common/edge_log.hpp"
#include "common/tool_sample.hpp"

namespace cnc::metrics {

struct LaserExposure {
    double lasered_path_mm = 0.0;  // path length the tool covered with the laser on
    double on_time_s = 0.0;        // laser on-time over that path (including time spent standing still)
    double mean_s_per_mm = 0.0;    // on_time / path
    double peak_s_per_mm = 0.0;    // the worst bin of kExposureBinMm along the lasered path
    double peak_at_path_mm = 0.0;  // where that bin starts, mm of lasered path from the first
};

inline constexpr double kExposureBinMm = 0.5;

// laser_exposure window by window (the streaming metrics; laser_exposure is the one-window case), so that neither
// the tool samples nor the laser log need be kept. Carried: the last sample, the totals, the open bin, the peak.
class LaserExposureFold {
public:
    using Samples = std::vector<ToolSample>::const_iterator;
    // The next tool samples [begin, end) in time order (the first pairs with the previous fold's last one);
    // `laser`: the laser pin from the previous fold's last sample on (its initial level the one there), with
    // every edge before the last of these samples.
    void fold(Samples begin, Samples end, const EdgeLog& laser);
    [[nodiscard]] LaserExposure finish() const;

private:
    void close_bin(LaserExposure& e) const;

    LaserExposure m_e;
    std::optional<ToolSample> m_last;
    double m_bin_start_mm = 0.0;
    double m_bin_time_s = 0.0;
    double m_bin_path_mm = 0.0;
};

// Between consecutive tool samples the tool is taken to move in a straight line at constant speed, and the
// laser's on-time in that interval is spread over the distance covered.
[[nodiscard]] LaserExposure laser_exposure(const std::vector<ToolSample>& tool, const EdgeLog& laser);

}  // namespace cnc::metrics
