// When the carriage's tool position is sampled, and the samples (mech::Carriage, MechanicsWorker): one at the
// start, one at every instant at which either axis steps (docs/metrics.md: contour error is sampled at every step
// event; steps of X and Y at one instant give one sample, the later overwriting, so that a diagonal step is not
// seen as an L) and, with a period, periodic samples in between for as long as an axis is not at rest (a dynamic
// carriage keeps moving between steps: it lags, rings and settles). The periodic samples fall on a fixed grid,
// the multiples of the period from t = 0. They start at the first grid time after the start of the run, a step or
// an enable change (each sets the set-points, so an axis moves on from there), and stop at the first one at
// which both axes are at rest. So an axis that is not at rest is sampled at every grid time, whatever the other
// does: what each axis is asked, and so its integration, does not depend on the other (which lets the mechanics
// worker integrate them on two threads).
// The caller keeps the clock: it reports the steps and enable changes and takes the periodic samples when due. At
// one instant the periodic sample comes before the steps (in the SystemC shell it is a timed event, the steps'
// samples follow the STEP edges by delta cycles).
#pragma once
#include <optional>
#include <vector>

#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "mechanics/core/carriage_drive.hpp"

namespace cnc::mech {

class ToolSampler {
public:
    // `period_ps` 0: samples at the steps only.
    ToolSampler(const CarriageDrive& x, const CarriageDrive& y, geom::Vec2 origin_mm, TimePs period_ps);

    // The sample at the start (t = 0); returns the time of the first periodic sample.
    [[nodiscard]] std::optional<TimePs> on_start(TimePs t_ps);
    // Either axis stepped at t: its sample; returns the time of the first periodic sample if this step starts them.
    [[nodiscard]] std::optional<TimePs> on_step(TimePs t_ps);
    // A driver's outputs were enabled or disabled at t (no sample: nothing has moved yet); returns the time of the
    // first periodic sample if this starts them.
    [[nodiscard]] std::optional<TimePs> on_enable(TimePs t_ps);
    // The periodic sample due at t; returns the time of the next one, or nothing once both axes are at rest.
    [[nodiscard]] std::optional<TimePs> on_period(TimePs t_ps);

    [[nodiscard]] const std::vector<ToolSample>& samples() const { return m_samples; }
    // The samples taken before t, handed over and forgotten (one at t or later may still be overwritten by a
    // step at its instant, so it stays).
    [[nodiscard]] std::vector<ToolSample> take_before(TimePs t_ps);

private:
    void sample(TimePs t_ps);
    // The axes' set-points changed at t: the periodic samples start at the next grid time, unless they run.
    std::optional<TimePs> start_periodic(TimePs t_ps);

    const CarriageDrive& m_x;
    const CarriageDrive& m_y;
    geom::Vec2 m_origin_mm;
    TimePs m_period_ps;
    bool m_periodic = false;  // periodic samples are due
    std::vector<ToolSample> m_samples;
};

}  // namespace cnc::mech
