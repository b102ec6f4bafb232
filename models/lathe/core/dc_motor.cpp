#include "lathe/core/dc_motor.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::lathe {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStallAmps = 4.0;   // §3.2.1 "up to 4 A": the stall current at 22 V
constexpr double kNoLoadAmps = 0.8;  // §3.2.2 "normal current about 0.8 A"
constexpr double kFirstOrderInductanceH = 1e-3;
constexpr double kSupplyVolts = 24.0;  // §2.3 supply
constexpr double kDiodeVolts = 1.0;    // 1N4007 forward drop at about 1 A (datasheet)
constexpr double kMaxStepS = 5e-6;     // RK4 step: 0.03 of the fastest time constant (L/R = 182 us)
constexpr double kLoadSmoothingRadPerS = 1.0;

}  // namespace

DcMotorParams derive_motor(std::optional<double> second_pole_per_s) {
    DcMotorParams p;
    const double w_full = kFullDutyPulsesPerS / kMotorSlots * 2.0 * kPi;
    p.r_ohm = kBridgeVolts / kStallAmps;
    p.kt_nm_per_a = (kBridgeVolts - p.r_ohm * kNoLoadAmps) / w_full;
    p.b_nm_s_per_rad = p.kt_nm_per_a * kNoLoadAmps / w_full;
    const double c0 = p.r_ohm * p.b_nm_s_per_rad + p.kt_nm_per_a * p.kt_nm_per_a;  // R b + Kt^2
    const double p1 = kDominantPolePerS;
    if (!second_pole_per_s) {
        // L J p1^2 - (L b + R J) p1 + c0 = 0 solved for J.
        p.l_h = kFirstOrderInductanceH;
        p.j_kg_m2 = (c0 - p.l_h * p.b_nm_s_per_rad * p1) / (p.r_ohm * p1 - p.l_h * p1 * p1);
        return p;
    }
    // L J = c0 / (p1 p2) and L b + R J = (p1 + p2) L J: with J = (sum L J - L b) / R, b L^2 - sum LJ L + R LJ = 0.
    const double p2 = *second_pole_per_s;
    const double lj = c0 / (p1 * p2);
    const double sum_lj = (p1 + p2) * lj;
    const double disc = sum_lj * sum_lj - 4.0 * p.b_nm_s_per_rad * p.r_ohm * lj;
    p.l_h = (sum_lj - std::sqrt(disc)) / (2.0 * p.b_nm_s_per_rad);
    p.j_kg_m2 = lj / p.l_h;
    return p;
}

double DcMotor::terminal_volts(BridgeMode mode, double drive_volts, double current_a) const {
    switch (mode) {
        case BridgeMode::Drive:
            return drive_volts;
        case BridgeMode::Brake:
            return 0.0;
        case BridgeMode::Coast:
            break;
    }
    const double clamp = kSupplyVolts + 2.0 * kDiodeVolts;
    return current_a > 0.0 ? -clamp : current_a < 0.0 ? clamp : 0.0;
}

void DcMotor::advance(double dt_s, BridgeMode mode, double drive_volts, double load_torque_nm) {
    // A shaft at rest, without current or load, on an open bridge stays so (the operator's waits cost nothing).
    if (mode == BridgeMode::Coast && m_s.current_a == 0.0 && m_s.omega_rad_per_s == 0.0 && load_torque_nm == 0.0) {
        return;
    }
    const int steps = std::max(1, static_cast<int>(std::ceil(dt_s / kMaxStepS)));
    const double h = dt_s / steps;
    const DcMotorParams& p = m_p;
    for (int k = 0; k < steps; ++k) {
        // The coasting current is clamped at 0: the diodes block the other direction.
        const bool open = mode == BridgeMode::Coast && m_s.current_a == 0.0;
        const double v = terminal_volts(mode, drive_volts, m_s.current_a);
        const auto deriv = [&](double w, double i, double& dw, double& di) {
            const double load = load_torque_nm == 0.0 ? 0.0 : load_torque_nm * std::tanh(w / kLoadSmoothingRadPerS);
            dw = (p.kt_nm_per_a * i - p.b_nm_s_per_rad * w - load) / p.j_kg_m2;
            di = open ? 0.0 : (v - p.r_ohm * i - p.kt_nm_per_a * w) / p.l_h;
        };
        const double w0 = m_s.omega_rad_per_s;
        const double i0 = m_s.current_a;
        double k1w, k1i, k2w, k2i, k3w, k3i, k4w, k4i;
        deriv(w0, i0, k1w, k1i);
        deriv(w0 + 0.5 * h * k1w, i0 + 0.5 * h * k1i, k2w, k2i);
        deriv(w0 + 0.5 * h * k2w, i0 + 0.5 * h * k2i, k3w, k3i);
        deriv(w0 + h * k3w, i0 + h * k3i, k4w, k4i);
        const double w1 = w0 + h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
        double i1 = i0 + h / 6.0 * (k1i + 2.0 * k2i + 2.0 * k3i + k4i);
        if (mode == BridgeMode::Coast && i0 * i1 <= 0.0) i1 = 0.0;
        m_s.angle_rad += h / 6.0 * (w0 + 2.0 * (w0 + 0.5 * h * k1w) + 2.0 * (w0 + 0.5 * h * k2w) + (w0 + h * k3w));
        m_s.omega_rad_per_s = w1;
        m_s.current_a = i1;
    }
}

}  // namespace cnc::lathe
