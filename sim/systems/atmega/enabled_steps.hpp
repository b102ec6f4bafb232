// The STEP pulses a DRV8825 acts on: rising edges while its active-low EN is low, with the falling edge that
// ends each of them. Seed 003 stops an axis by EN while its timer keeps toggling STEP (§4.3-4.5), so the raw pin
// carries pulses no motor sees; the metrics count what a logic analyser triggered on STEP and qualified by
// EN = 0 would count (spec seed-003 §5, "the caliper").
#pragma once
#include "common/edge_log.hpp"

namespace cnc::sim {

// `step` and `n_enbl` in time order. A STEP edge at the same instant as an EN change sees the EN level before
// the change (the driver samples the level it had). The result keeps `step`'s name and initial level low.
[[nodiscard]] EdgeLog enabled_steps(const EdgeLog& step, const EdgeLog& n_enbl);

}  // namespace cnc::sim
