// The lathe's spindle, turned by the lathe's own motor (seed 002 §1.1, §2.3: the master, not controlled). Set to
// `rpm`, it slows under the cutting torque with a linear speed droop, reached as a first-order lag:
//   d(deficit)/dt = (droop x T_cut - deficit) / time_constant,   deficit = set speed - speed.
// A motor without speed feedback loses speed in proportion to its load torque: an induction motor by its slip,
// a brush motor on an open-loop controller by its I R drop. The seed gives no spindle drive at all;
// the defaults (lathe.spindle.*) are estimates stated in docs/metrics.md "Lathe".
#pragma once

namespace cnc::lathe {

struct SpindleParams {
    double rpm = 0.0;               // set speed, no load
    double droop_pct_per_nm = 0.0;  // steady speed loss per N m of torque at the spindle, % of rpm
    double time_constant_s = 0.0;   // 0: the droop follows the torque at once
};

class Spindle {
public:
    explicit Spindle(const SpindleParams& p) : m_p(p), m_rev_per_s(p.rpm / 60.0) {}

    // Runs from the last time to t_s with `torque_nm` at the spindle (held over the step).
    void advance_to(double t_s, double torque_nm);
    // Revolutions since the start.
    [[nodiscard]] double rev() const { return m_rev_per_s * m_t_s - m_lost_rev; }
    [[nodiscard]] double rpm() const { return (m_rev_per_s - m_deficit_rev_per_s) * 60.0; }

private:
    SpindleParams m_p;
    double m_rev_per_s;
    double m_t_s = 0.0;
    double m_deficit_rev_per_s = 0.0;
    double m_lost_rev = 0.0;  // the revolutions the droop has cost so far
};

// The torque the tool asks of the spindle: the cutting force k_c x chip area (depth of cut x feed per
// revolution; Kienzle's force with its exponent taken as 1) at the workpiece's radius.
struct CutParams {
    double depth_mm = 0.0;
    double kc_n_per_mm2 = 0.0;
    double diameter_mm = 0.0;
};
[[nodiscard]] double cutting_torque_nm(const CutParams& cut, double feed_mm_per_rev);

}  // namespace cnc::lathe
