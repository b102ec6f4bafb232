// Step-size control of an embedded 5(4) Runge-Kutta pair: the PI controller of Hairer's DOPRI5 code
// (Hairer, Norsett, Wanner, "Solving Ordinary Differential Equations I", 2nd ed., §II.4, and the code's
// "stabilized step size control" with beta = 0.04). The new step follows the error ratio of this step and,
// weakly, of the last accepted one, which damps the grow-reject-shrink cycle an error estimate that swings
// with an oscillation (the rotor's ringing) drives a plain err^(-1/5) rule into; after a rejection the next
// accepted step does not grow.
#pragma once
#include <algorithm>
#include <cmath>

namespace cnc::mech {

class StepSizeControl {
public:
    // The step to try next after a step of dt with error ratio err (error / tolerance; accepted if <= 1).
    double next_step_s(double dt, double err) {
        const double log_err = std::log(std::max(err, 1e-300));  // an exact step grows at the most
        if (err > 1.0) {
            m_rejected = true;
            return dt / std::min(kMaxShrink, std::exp(kExponent * log_err) / kSafety);
        }
        const double fac =
            std::clamp(std::exp(kExponent * log_err - kBeta * m_log_err_old) / kSafety, kMaxGrowthInv, kMaxShrink);
        m_log_err_old = std::max(log_err, kLogErrOldFloor);
        const double next = dt / fac;
        const bool was_rejected = m_rejected;
        m_rejected = false;
        return was_rejected ? std::min(next, dt) : next;
    }

private:
    static constexpr double kBeta = 0.04;                    // DOPRI5's default for the PI controller
    static constexpr double kExponent = 0.2 - 0.75 * kBeta;  // 1/5 for a 5(4) pair, less the PI share
    static constexpr double kSafety = 0.9;
    static constexpr double kMaxShrink = 5.0;     // a step shrinks to at most 1/5 ...
    static constexpr double kMaxGrowthInv = 0.1;  // ... and grows to at most 10 x (DOPRI5's fac1, fac2)
    static constexpr double kLogErrOldFloor = -9.210340371976184;  // ln 1e-4: DOPRI5 keeps at least 1e-4
    double m_log_err_old = kLogErrOldFloor;
    bool m_rejected = false;
};

}  // namespace cnc::mech
