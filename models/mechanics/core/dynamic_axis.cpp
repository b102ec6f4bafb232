#include "mechanics/core/dynamic_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "common/math_constants.hpp"
#include "mechanics/core/drv8825_modes.hpp"

namespace cnc::mech {

namespace {

constexpr double kRadToDeg = 180.0 / kPi;
constexpr int kFullStepsPerElectricalPeriod = 4;  // two-phase motor: 4 x 90 electrical deg
// A slip counts once the rotor is past the unstable equilibrium, half a period from its own, by this much more: a
// rotor hovering on it, pushed to and fro by single microsteps (2.8 electrical deg at 1/32), has not slipped.
constexpr double kSlipHysteresisRad = kPi / 4.0;
// Steps further apart than this are starts from rest, not a commanded speed (1/32 step at 0.1 s: 2 mm/min).
constexpr TimePs kRippleMaxStepGapPs = 100 * kPsPerMs;

}  // namespace

DynamicAxis::DynamicAxis(const AxisParams& params, const IntegratorTolerances& tol) : m_integrator(params, tol) {
    apply_setpoints();
}

void DynamicAxis::advance(TimePs t_ps) const {
    if (t_ps == m_tracked_ps) return;  // a second query at the same instant: nothing moved
    const bool resting = m_integrator.at_rest();
    m_integrator.advance_to(ps_to_s(t_ps));
    // A resting axis is where it came to rest, its load angle what it was then: asking it again records nothing,
    // so that how often it is asked while it rests (the other axis's steps and samples) changes none of its figures.
    if (!resting) track_load_angle(t_ps);
    m_tracked_ps = t_ps;
}

double DynamicAxis::lag_electrical_rad() const {
    const HybridStepperParams& motor = m_integrator.ode().params().motor;
    return motor.rotor_teeth * (commanded_shaft_deg() / kRadToDeg - m_integrator.state()[kTheta]);
}

void DynamicAxis::track_load_angle(TimePs t_ps) const {
    if (!m_enabled) return;
    const double lag_rad = lag_electrical_rad();
    if (std::abs(lag_rad - 2.0 * kPi * static_cast<double>(m_slip_periods)) > kPi + kSlipHysteresisRad) {
        const auto periods = static_cast<std::int64_t>(std::llround(lag_rad / (2.0 * kPi)));
        const int steps = static_cast<int>(periods - m_slip_periods) * kFullStepsPerElectricalPeriod;
        m_stats.lost_full_steps += std::abs(steps);
        if (m_stats.events.size() < kMaxLostStepEvents) m_stats.events.push_back({t_ps, steps});
        m_slip_periods = periods;
    }
    const double load_angle_deg = std::abs(lag_rad - 2.0 * kPi * static_cast<double>(m_slip_periods)) * kRadToDeg;
    m_stats.load_angle_deg_trace.add(t_ps, load_angle_deg);
    if (load_angle_deg > m_stats.peak_load_angle_deg) {
        m_stats.peak_load_angle_deg = load_angle_deg;
        m_stats.peak_load_angle_ps = t_ps;
    }
}

void DynamicAxis::apply_setpoints() {
    const DriverElectrics& drv = m_integrator.ode().params().driver;
    m_integrator.set_setpoints({winding_setpoints(m_units, drv, m_enabled), m_external_torque_nm});
}

void DynamicAxis::on_microstep(TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) {
    advance(t_ps);
    const std::int64_t previous = m_units;
    m_units = microstep_index * (kIndexerUnitsPerFullStep / microsteps_per_full_step);
    m_tracked_ps = -1;  // the command moved: the load angle changed at this instant
    track_ripple(t_ps, previous);
    apply_setpoints();
}

void DynamicAxis::track_ripple(TimePs t_ps, std::int64_t previous_units) {
    const TimePs gap = t_ps - m_last_microstep_ps;
    if (m_last_microstep_ps >= 0 && gap > 0 && gap < kRippleMaxStepGapPs && m_enabled) {
        const AxisParams& p = m_integrator.ode().params();
        const double mm_per_unit = p.load.travel_per_rev_mm / (4.0 * p.motor.rotor_teeth * kIndexerUnitsPerFullStep);
        const double commanded = static_cast<double>(m_units - previous_units) * mm_per_unit / ps_to_s(gap);
        const double diff = std::abs(carriage_velocity_mm_s(t_ps) - commanded);
        m_ripple_sum_sq += diff * diff;
        ++m_stats.ripple_samples;
        m_stats.velocity_ripple_rms_mm_s = std::sqrt(m_ripple_sum_sq / static_cast<double>(m_stats.ripple_samples));
        m_stats.velocity_ripple_peak_mm_s = std::max(m_stats.velocity_ripple_peak_mm_s, diff);
    }
    m_last_microstep_ps = t_ps;
}

void DynamicAxis::on_enable(TimePs t_ps, bool enabled) {
    advance(t_ps);
    // No new reference at re-enabling: the driver ignores STEP while disabled, so the commanded position held, and a
    // rotor that coasted or was pushed more than half an electrical period meanwhile is pulled into another period
    // than the commanded one: steps lost (a carriage coasting after its driver is switched off mid-motion), counted
    // at the enable.
    m_enabled = enabled;
    apply_setpoints();
    if (enabled) track_load_angle(t_ps);
}

void DynamicAxis::set_external_torque(TimePs t_ps, double torque_nm) {
    advance(t_ps);
    m_external_torque_nm = torque_nm;
    apply_setpoints();
}

double DynamicAxis::shaft_angle_deg(TimePs t_ps) const {
    advance(t_ps);
    return m_integrator.state()[kTheta] * kRadToDeg;
}

double DynamicAxis::commanded_shaft_deg() const {
    const HybridStepperParams& motor = m_integrator.ode().params().motor;
    return static_cast<double>(m_units) / kIndexerUnitsPerFullStep * motor.full_step_rad() * kRadToDeg;
}

double DynamicAxis::carriage_mm(TimePs t_ps) const {
    advance(t_ps);
    const AxisParams& p = m_integrator.ode().params();
    if (p.load.kind == DriveKind::Free) return m_integrator.state()[kTheta] * travel_m_per_rad(p.load) * 1e3;
    return m_integrator.state()[kX] * 1e3;
}

double DynamicAxis::carriage_velocity_mm_s(TimePs t_ps) const {
    advance(t_ps);
    const AxisParams& p = m_integrator.ode().params();
    if (p.load.kind == DriveKind::Free) return m_integrator.state()[kOmega] * travel_m_per_rad(p.load) * 1e3;
    return m_integrator.state()[kV] * 1e3;
}

}  // namespace cnc::mech
