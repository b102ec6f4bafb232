// The host's trajectory clock against simulated time. The servo thread samples the planner at trajectory time
// tau_n in period n and the sample stands for the nominal period start n * T (LinuxCNC's motion controller
// advances its trajectory by exactly one period per invocation, whatever the wake-up latency). tau runs with the
// clock except while the host holds it at a rest point (see servo_core.hpp), so it is piecewise linear between
// the knots (n * T, tau_n): that is the commanded timed trajectory the metrics compare the tool with.
#pragma once
#include <vector>

#include "common/units.hpp"

namespace cnc::host::servo {

class TrajectoryClock {
public:
    // Knots in nondecreasing order of both t and tau.
    void add(TimePs t_ps, double tau_s);

    struct Reading {
        double tau_s = 0.0;
        double rate = 0.0;  // d tau / d t
    };
    // tau at t, linear between knots, held before the first and after the last (0 without knots).
    [[nodiscard]] double tau_at(TimePs t_ps) const { return at(t_ps).tau_s; }
    // d tau / d t at t (1 while the clock runs, 0 in a hold or outside the knots).
    [[nodiscard]] double rate_at(TimePs t_ps) const { return at(t_ps).rate; }
    [[nodiscard]] Reading at(TimePs t_ps) const;
    // The last time at which tau(t) <= tau: when the clock leaves tau (the end of a hold there).
    [[nodiscard]] TimePs depart_time(double tau_s) const;
    // The first knot's time, also once it is dropped.
    [[nodiscard]] TimePs t_begin_ps() const { return m_t_first_ps; }
    [[nodiscard]] TimePs t_end_ps() const { return m_t.empty() ? 0 : m_t.back(); }
    [[nodiscard]] std::size_t size() const { return m_t.size(); }  // the knots kept
    // Drops the knots before the last one at or before both t_ps and tau_s, so that at(t) for t >= t_ps and
    // depart_time(tau) for tau >= tau_s read as before (a long job's clock then holds only what is still read).
    void drop_before(TimePs t_ps, double tau_s);

private:
    TimePs m_t_first_ps = 0;
    std::vector<TimePs> m_t;
    std::vector<double> m_tau;
};

}  // namespace cnc::host::servo
