// Integrating factor (Lawson's method) for the windings whose bridge regulates during an integration step
// (axis_integrator.hpp): such a winding is integrated as z = (i - i_ref) exp(rate (t - t0)), which stays
// constant while the bridge regulates (drv8825_current.hpp), so the current's decay at 1/tau + R/L (about
// 50,000 /s), stiff for an explicit method, costs no steps. A winding whose bridge sits at +-VMOT (its
// current ramps at L/R) is integrated as it is.
// The decaying current error also jerks the rotor: it adds K_m g(psi) z exp(-rate (t - t0)) / J to the
// shaft's acceleration (g = -sin psi for winding a, cos psi for b). The frame carries that term's integral
// with psi held at the step's start, omega~ = omega - K_m g(psi0) z (1 - exp(-rate (t - t0))) / (J rate),
// an exact change of variables, so that only the part from the angle's change within the step (a few
// per cent of it) is left to the error control: otherwise every end of a current ramp, where the winding
// settles onto its set-point within 20 us, would force steps of that size.
// The decay exp(-rate (t - t0)) is needed at each Dormand-Prince stage: the frame of a step of known length
// takes the stages' decays from one exp (StageDecays) instead of one each.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>

#include "mechanics/core/axis_ode.hpp"

namespace cnc::mech {

class CurrentFrame {
public:
    // `angle0`: the rotor angle of x0 (hybrid_stepper.hpp); `dt_s`: the step's length.
    CurrentFrame(const AxisOde& ode, const AxisModes& modes, const AxisState& x0, RotorAngle angle0, double t0_s,
                 double dt_s)
        : m_ode(ode),
          m_modes(modes),
          m_angle(ode.params().motor, x0[kTheta], angle0),
          m_t0_s(t0_s),
          m_rate_per_s(ode.regulation_rate_per_s()),
          m_inv_rate_s(1.0 / m_rate_per_s),
          m_stages(regulated(0) || regulated(1) ? StageDecays(t0_s, dt_s, m_rate_per_s) : StageDecays()) {
        const WindingSetpoints& sp = ode.setpoints().current;
        m_offset_a = {regulated(0) ? sp.a_a : 0.0, regulated(1) ? sp.b_a : 0.0};
        const double k = ode.alpha_per_a();
        m_alpha_per_a = {regulated(0) ? -k * angle0.sin_psi : 0.0, regulated(1) ? k * angle0.cos_psi : 0.0};
    }

    // The physical state and its derivative at t0 into the frame.
    void enter(AxisState& x, AxisState& dxdt) const {
        for (int k = 0; k < 2; ++k) {
            if (!regulated(k)) continue;
            const double w = x[k] - m_offset_a[k];
            x[k] = w;
            dxdt[k] += m_rate_per_s * w;
        }
        dxdt[kOmega] -= settling_alpha(x);
    }
    // The frame's state at t back to the physical one.
    void leave(double t_s, AxisState& y) const { leave_with(y, decay(t_s)); }
    // The same for a state and its derivative.
    void leave(double t_s, AxisState& y, AxisState& dy) const {
        const double d = decay(t_s);
        dy[kOmega] += settling_alpha(y) * d;
        leave_with(y, d);
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) dy[k] = -m_rate_per_s * (y[k] - m_offset_a[k]);
        }
    }
    // The rotor angle of a shaft angle within the step.
    [[nodiscard]] RotorAngle angle(double theta_rad) const { return m_angle.at(theta_rad); }
    // The margins of the modes at a physical state within the step (axis_ode.hpp).
    [[nodiscard]] AxisOde::ModeMargins mode_margins(const AxisState& x) const {
        return m_ode.mode_margins(x, m_modes, m_angle.at(x[kTheta]));
    }
    // The equations of motion in the frame.
    void operator()(const AxisState& y, AxisState& dy, double t_s) const {
        if (!regulated(0) && !regulated(1)) {
            m_ode.derivative(y, dy, m_modes, m_angle.at(y[kTheta]));
            return;
        }
        const double d = decay(t_s);
        AxisState x = y;
        leave_with(x, d);
        m_ode.derivative(x, dy, m_modes, m_angle.at(x[kTheta]));
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) dy[k] = 0.0;  // the decay is the frame's: d/dt (i - i_ref) = -rate (i - i_ref)
        }
        dy[kOmega] -= settling_alpha(y) * d;
    }

private:
    // The decays at the stage times of runge_kutta_dopri5::do_step (t0 + c dt, c = 1/5, 3/10, 4/5, 8/9, 1),
    // each time computed as odeint computes it so that the stages find theirs by equality. With
    // u = exp(-rate dt / 90) they are u^18, u^27, u^72, u^80 and u^90: one exp and ten products (a few ulp
    // from exp of each, which the current error's 1e-2 A scale turns into 1e-17 A).
    struct StageDecays {
        static constexpr std::size_t kStages = 5;
        StageDecays() = default;
        StageDecays(double t0_s, double dt_s, double rate_per_s) {
            const double u = std::exp(-rate_per_s * dt_s * (1.0 / 90.0));
            const double u2 = u * u;
            const double u4 = u2 * u2;
            const double u8 = u4 * u4;
            const double u9 = u8 * u;
            const double u18 = u9 * u9;
            const double u36 = u18 * u18;
            const double u72 = u36 * u36;
            t_s = {t0_s + dt_s * (1.0 / 5.0), t0_s + dt_s * (3.0 / 10.0), t0_s + dt_s * (4.0 / 5.0),
                   t0_s + dt_s * (8.0 / 9.0), t0_s + dt_s};
            decay = {u18, u18 * u9, u72, u72 * u8, u72 * u18};
        }
        std::array<double, kStages> t_s{};
        std::array<double, kStages> decay{};
    };

    [[nodiscard]] bool regulated(int k) const { return m_modes.bridges[k] == BridgeMode::Regulating; }
    [[nodiscard]] double decay(double t_s) const {
        if (!regulated(0) && !regulated(1)) return 1.0;
        for (std::size_t k = 0; k < StageDecays::kStages; ++k) {
            if (t_s == m_stages.t_s[k]) return m_stages.decay[k];
        }
        return std::exp(-m_rate_per_s * (t_s - m_t0_s));
    }
    // The shaft acceleration of the frame's current errors at the step's start angle, rad/s2 (times the decay).
    [[nodiscard]] double settling_alpha(const AxisState& y) const {
        return m_alpha_per_a[0] * y[kIa] + m_alpha_per_a[1] * y[kIb];
    }
    void leave_with(AxisState& y, double d) const {
        if (!regulated(0) && !regulated(1)) return;
        y[kOmega] += settling_alpha(y) * (1.0 - d) * m_inv_rate_s;
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) y[k] = m_offset_a[k] + y[k] * d;
        }
    }

    const AxisOde& m_ode;
    AxisModes m_modes;
    RotorAngleNear m_angle;  // the shaft moves little within a step
    double m_t0_s;
    double m_rate_per_s;
    double m_inv_rate_s;
    StageDecays m_stages;
    std::array<double, 2> m_offset_a{};
    std::array<double, 2> m_alpha_per_a{};  // K_m g(psi0) / J per winding, 0 for a winding that ramps
};

}  // namespace cnc::mech
