// The streaming metrics of an architecture's run (run/metrics_feed.hpp) on its machine's carriage: they take the
// carriage's tool samples as they measure, and with the dynamic axes on worker threads (mech::Carriage) measure only
// as far as the workers' samples are ready, never waiting for them.
#pragma once
#include <optional>
#include <vector>

#include "run/machine.hpp"
#include "run/metrics_feed.hpp"

namespace cnc::sim {

// Starts `feed` before the simulation (the recorder's logs give the pins' initial levels); the laser pin is "laser".
void feed_on_carriage(std::optional<MetricsFeed>& feed, EdgeRecorder& rec, const std::vector<AxisPins>& axes,
                      Machine& machine, bool detail, metrics::PieceMeasured on_piece = {});

}  // namespace cnc::sim
