#include "metrics/sync_error.hpp"

#include <cmath>

#include "metrics/stats.hpp"

namespace cnc::metrics {

SyncResult compute_sync(const RunInput& in, const EdgeIndex& idx) {
    SyncResult out;
    const std::size_t n_axes = idx.axes.size();
    out.axis_max_abs_ns.assign(n_axes, std::nullopt);
    out.move_axis_max_abs_ns.assign(in.moves.size(), std::vector<std::optional<double>>(n_axes));
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        if (!idx.move_first_edge_ps[m]) continue;
        const TimePs t0 = *idx.move_first_edge_ps[m];
        for (std::size_t a = 0; a < n_axes && a < 2; ++a) {
            const double rate = in.moves[m].rate_steps_per_s[a];
            const EdgeRange r = idx.by_move[a][m];
            if (rate <= 0.0 || r.empty()) continue;
            const long double period_ps = static_cast<long double>(kPsPerSec) / rate;
            double worst = 0.0;
            for (std::size_t k = 0; k < r.size(); ++k) {
                const long double ideal = period_ps * static_cast<long double>(k);
                const long double actual = static_cast<long double>(idx.axes[a].rising[r.begin + k] - t0);
                worst = std::max(worst, static_cast<double>(std::fabs(actual - ideal) / 1000.0L));
            }
            out.move_axis_max_abs_ns[m][a] = worst;
            keep_max(out.axis_max_abs_ns[a], worst);
            keep_max(out.max_abs_ns, worst);
        }
    }
    return out;
}

}  // namespace cnc::metrics
