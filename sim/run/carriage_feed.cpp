#include "run/carriage_feed.hpp"

#include <utility>

namespace cnc::sim {

void feed_on_carriage(std::optional<MetricsFeed>& feed, EdgeRecorder& rec, const std::vector<AxisPins>& axes,
                      Machine& machine, bool detail, metrics::PieceMeasured on_piece) {
    feed.emplace(
        rec, axes, "laser", [&machine](TimePs t_ps) { return machine.carriage().take_samples_before(t_ps); }, detail,
        std::move(on_piece));
    if (machine.mechanics_on_worker()) feed->stay_behind([&machine] { return machine.carriage().samples_ready_ps(); });
}

}  // namespace cnc::sim
