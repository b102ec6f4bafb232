// The STEP pulses a DRV8825 acts on: rising edges while its enable input is active, with the falling edge that
// ends each of them. Seed 003 stops an axis by EN while its timer keeps toggling STEP (App. A2-A4), so the raw pin
// carries pulses no motor sees; the metrics count what a logic analyser triggered on STEP and qualified by the
// enable would count: our stand-in for the caliper of seed 003's abstract, whose measurements the thesis does not
// give. `cncsim analyze --enable` applies the same rule.
#pragma once
#include "common/edge_log.hpp"

namespace cnc::metrics {

// The level at which the enable input lets the driver step: the DRV8825's nENBL is active low.
enum class EnableLevel { ActiveHigh, ActiveLow };

// The same rule over a run read piece by piece (a streamed run hands its pins over slice by slice): the enable
// level and whether a pulse is under way are carried from one piece to the next.
class EnabledStepsFold {
public:
    EnabledStepsFold(bool enable_initial, EnableLevel active);
    // `step` and `enable`: both pins' edges before the same instant, after those of the previous call, in time
    // order. The pulses the driver acts on among them (named as `step`, initial level low).
    [[nodiscard]] EdgeLog add(const EdgeLog& step, const EdgeLog& enable);

private:
    bool m_enabled_level;
    bool m_enabled;
    bool m_in_pulse = false;
};

// `step` and `enable` in time order. A STEP edge at the same instant as an enable change sees the level before
// the change (the driver samples the level it had). The result keeps `step`'s name and initial level low.
[[nodiscard]] EdgeLog enabled_steps(const EdgeLog& step, const EdgeLog& enable, EnableLevel active);

}  // namespace cnc::metrics
