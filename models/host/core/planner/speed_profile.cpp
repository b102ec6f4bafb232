#include "host/core/planner/speed_profile.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::host::planner {

namespace {

// Peak-to-change ratios of the quintic speed blend (derived in speed_profile.hpp).
constexpr double kQuinticPeakAccel = 15.0 / 8.0;
constexpr double kQuinticPeakJerk = 5.773502691896257;  // 10 / sqrt(3)
// Bisection steps for the peak speed of a jerk-limited piece: 2^-100 of the bracket, below double resolution.
constexpr int kPeakBisectionSteps = 100;

// Shortest quintic blend: T = max(c1 dv, sqrt(c2 dv)).
double quintic_c1(const PathLimits& l) {
    return kQuinticPeakAccel / l.accel_mm_per_s2;
}
double quintic_c2(const PathLimits& l) {
    return kQuinticPeakJerk / l.jerk_mm_per_s3;
}

PathState transition_state(Profile shape, double v0, double v1, double duration_s, double t_s) {
    const double dv = v1 - v0;
    if (shape == Profile::Trapezoidal) {
        const double a = dv / duration_s;
        return PathState{v0 * t_s + 0.5 * a * t_s * t_s, v0 + a * t_s, a};
    }
    const double tau = t_s / duration_s;
    const double tau2 = tau * tau;
    const double tau3 = tau2 * tau;
    const double p = tau3 * (10.0 - 15.0 * tau + 6.0 * tau2);
    const double p_integral = tau2 * tau2 * (2.5 - 3.0 * tau + tau2);  // integral of p, 1/2 at tau = 1
    const double p_slope = 30.0 * tau2 * (1.0 - tau) * (1.0 - tau);
    return PathState{v0 * t_s + dv * duration_s * p_integral, v0 + dv * p, dv / duration_s * p_slope};
}

}  // namespace

double transition_time_s(Profile shape, double v0, double v1, const PathLimits& limits) {
    const double dv = std::fabs(v1 - v0);
    if (shape == Profile::Trapezoidal) return dv / limits.accel_mm_per_s2;
    return std::max(quintic_c1(limits) * dv, std::sqrt(quintic_c2(limits) * dv));
}

double transition_distance_mm(Profile shape, double v0, double v1, const PathLimits& limits) {
    return 0.5 * (v0 + v1) * transition_time_s(shape, v0, v1, limits);
}

double reachable_speed(Profile shape, double v0, double distance_mm, const PathLimits& limits) {
    if (distance_mm <= 0.0) return v0;
    if (shape == Profile::Trapezoidal) return std::sqrt(v0 * v0 + 2.0 * limits.accel_mm_per_s2 * distance_mm);
    const double c1 = quintic_c1(limits);
    const double c2 = quintic_c2(limits);
    // Above dv_split the acceleration limit sets T (T = c1 dv), below it the jerk limit (T = sqrt(c2 dv)).
    const double dv_split = c2 / (c1 * c1);
    if (distance_mm >= (v0 + 0.5 * dv_split) * c1 * dv_split) {
        // (v0 + dv/2) c1 dv = D, solved in the cancellation-free form.
        const double k = 2.0 * distance_mm / c1;
        return v0 + k / (v0 + std::sqrt(v0 * v0 + k));
    }
    // (v0 + dv/2) sqrt(c2 dv) = D with x = sqrt(dv): x^3 + p x + q = 0, p = 2 v0 >= 0, q = -2 D / sqrt(c2) < 0.
    // One real root (Cardano, x = A + B with A B = -p/3), written as x = -q / (A^2 - A B + B^2) so that no
    // difference of near-equal terms occurs.
    const double p = 2.0 * v0;
    const double q = -2.0 * distance_mm / std::sqrt(c2);
    const double a = std::cbrt(-0.5 * q + std::sqrt(0.25 * q * q + p * p * p / 27.0));
    const double b = p / (3.0 * a);
    const double x = -q / (a * a + p / 3.0 + b * b);
    return v0 + x * x;
}

PathState SpeedProfile::at(double t_s) const {
    const double t = std::clamp(t_s, 0.0, duration_s());
    PathState st{};
    if (t < rise_s) {
        st = transition_state(shape, entry_mm_per_s, peak_mm_per_s, rise_s, t);
    } else if (t < rise_s + cruise_s || fall_s <= 0.0) {
        const double d_rise = 0.5 * (entry_mm_per_s + peak_mm_per_s) * rise_s;
        st = PathState{d_rise + peak_mm_per_s * (t - rise_s), peak_mm_per_s, 0.0};
    } else {
        const double d_before = 0.5 * (entry_mm_per_s + peak_mm_per_s) * rise_s + peak_mm_per_s * cruise_s;
        st = transition_state(shape, peak_mm_per_s, exit_mm_per_s, fall_s, t - rise_s - cruise_s);
        st.s_mm += d_before;
    }
    st.s_mm = std::clamp(st.s_mm, 0.0, length_mm);
    if (t >= duration_s()) {  // exact end state (v0 + (dv/T) T can miss v1 by an ulp)
        st.s_mm = length_mm;
        st.v_mm_per_s = exit_mm_per_s;
    }
    return st;
}

SpeedProfile make_speed_profile(Profile shape, double length_mm, double entry_mm_per_s, double exit_mm_per_s,
                                const PathLimits& limits) {
    SpeedProfile sp;
    sp.shape = shape;
    sp.limits = limits;
    sp.length_mm = length_mm;
    sp.entry_mm_per_s = entry_mm_per_s;
    sp.exit_mm_per_s = exit_mm_per_s;
    const double floor_v = std::max(entry_mm_per_s, exit_mm_per_s);
    const auto needed = [&](double peak) {
        return transition_distance_mm(shape, entry_mm_per_s, peak, limits) +
               transition_distance_mm(shape, peak, exit_mm_per_s, limits);
    };
    double peak = limits.velocity_mm_per_s;
    if (needed(peak) > length_mm) {
        if (shape == Profile::Trapezoidal) {
            const double a = limits.accel_mm_per_s2;
            peak = std::sqrt(a * length_mm + 0.5 * (entry_mm_per_s * entry_mm_per_s + exit_mm_per_s * exit_mm_per_s));
        } else {
            double lo = floor_v;
            double hi = peak;
            for (int i = 0; i < kPeakBisectionSteps && lo < hi; ++i) {
                const double mid = 0.5 * (lo + hi);
                (needed(mid) <= length_mm ? lo : hi) = mid;
            }
            peak = lo;
        }
    }
    peak = std::clamp(peak, floor_v, std::max(floor_v, limits.velocity_mm_per_s));
    sp.peak_mm_per_s = peak;
    sp.rise_s = transition_time_s(shape, entry_mm_per_s, peak, limits);
    sp.fall_s = transition_time_s(shape, peak, exit_mm_per_s, limits);
    const double cruise_mm = std::max(0.0, length_mm - needed(peak));
    sp.cruise_s = peak > 0.0 ? cruise_mm / peak : 0.0;
    return sp;
}

}  // namespace cnc::host::planner
