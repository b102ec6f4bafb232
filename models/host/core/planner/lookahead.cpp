#include "host/core/planner/lookahead.hpp"

#include <algorithm>
#include <cstddef>

#include "host/core/planner/speed_profile.hpp"

namespace cnc::host::planner {

std::vector<double> boundary_speeds(const std::vector<LookaheadPiece>& pieces, Profile shape, int lookahead_moves) {
    const std::size_t n = pieces.size();
    std::vector<double> speeds(n + 1, 0.0);
    std::size_t window_end = 0;  // one past the window's last piece
    for (std::size_t k = 0; k < n; ++k) {
        const long long last_visible = static_cast<long long>(pieces[k].last_move_needed) + lookahead_moves - 1;
        window_end = std::max(window_end, k + 1);
        while (window_end < n && pieces[window_end].last_move_needed <= last_visible) ++window_end;
        // Backward from rest at the window's end to the end of piece k.
        double exit_cap = 0.0;
        for (std::size_t j = window_end; --j > k;) {
            exit_cap = std::min(pieces[j].entry_cap_mm_per_s,
                                reachable_speed(shape, exit_cap, pieces[j].length_mm, pieces[j].limits));
        }
        speeds[k + 1] = std::min(exit_cap, reachable_speed(shape, speeds[k], pieces[k].length_mm, pieces[k].limits));
    }
    return speeds;
}

}  // namespace cnc::host::planner
