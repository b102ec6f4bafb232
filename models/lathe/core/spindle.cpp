#include "lathe/core/spindle.hpp"

#include <cmath>

namespace cnc::lathe {

// The first-order lag solved exactly over the step (the torque held), its integral giving the revolutions lost:
// with d_inf the target deficit, d(t) = d_inf + (d0 - d_inf) e^(-t/tau) and the loss d_inf t + (d0 - d_inf)
// tau (1 - e^(-t/tau)). With no load and no deficit the loss stays exactly 0 (rev() = rpm / 60 x t).
void Spindle::advance_to(double t_s, double torque_nm) {
    const double dt = t_s - m_t_s;
    m_t_s = t_s;
    const double target = m_rev_per_s * m_p.droop_pct_per_nm / 100.0 * torque_nm;
    if (target == 0.0 && m_deficit_rev_per_s == 0.0) return;
    if (m_p.time_constant_s <= 0.0) {
        m_deficit_rev_per_s = target;
        m_lost_rev += target * dt;
        return;
    }
    const double decay = std::exp(-dt / m_p.time_constant_s);
    const double d0 = m_deficit_rev_per_s - target;
    m_lost_rev += target * dt + d0 * m_p.time_constant_s * (1.0 - decay);
    m_deficit_rev_per_s = target + d0 * decay;
}

double cutting_torque_nm(const CutParams& cut, double feed_mm_per_rev) {
    const double force_n = cut.kc_n_per_mm2 * cut.depth_mm * feed_mm_per_rev;
    return force_n * cut.diameter_mm / 2.0 / 1000.0;
}

}  // namespace cnc::lathe
