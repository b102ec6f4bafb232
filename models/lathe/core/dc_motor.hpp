// The leadscrew's DC gear-motor (seed 002 §2.3, §4.3) driven by the L298: a permanent-magnet brushed motor,
//   J dw/dt = Kt i - b w - T_load,   L di/dt = V - R i - Kt w   (§1.3.2 eqs. 3-6, with Kb = Kt in SI units),
// integrated by fixed-step RK4 between the bridge's switching instants.
//
// The thesis identified only duty -> motor pulses/s, G(s) = 2.0866 / (s/74.29 + 1) (§4.3: 2136.75 pulses/s at
// 100 % duty, dominant pole -74.29 s^-1, a second pole near -163.6 in the two-exponential fit), and gives no R,
// L, J, b or Kt. derive_motor() chooses a consistent set:
//   * w_full = 2136.75 pulses/s / 30 slots * 2 pi = 447.52 rad/s at the motor shaft with 22 V on the terminals
//     (24 V supply less the L298's 2 V, §2.3).
//   * R = 5.5 ohm: the 4 A the thesis quotes as the motor's peak (§3.2.1) is the stall current at 22 V.
//   * i = 0.8 A at w_full, the "normal current" of §3.2.2 read as the no-load current: Kt = (22 - 5.5 * 0.8) / w_full
//     = 0.03933 N m/A, and b = Kt * 0.8 / w_full = 7.03e-5 N m s (the friction that draws it). The DC gain
//     Kt / (R b + Kt^2) is then 447.52 / 22 rad/s/V, i.e. K = 2.0866 pulses/s per duty count exactly.
//   * First order (default): L = 1 mH (an electrical pole near -5400 s^-1, far above the identified one) and J
//     such that -74.29 s^-1 is a root of L J s^2 + (L b + R J) s + (R b + Kt^2): J = 4.79e-6 kg m^2 (the
//     gearbox, belt, leadscrew and carriage reflected to the motor shaft, as the identification saw them).
//   * Two poles (option): L and J from the pole sum and product, -74.29 and -163.6: L = 24.2 mH, J = 6.57e-6
//     kg m^2 (the smaller of the two roots for L; the other, 0.51 H, is no small motor's).
#pragma once
#include <optional>

namespace cnc::lathe {

struct DcMotorParams {
    double r_ohm = 0.0;
    double l_h = 0.0;
    double j_kg_m2 = 0.0;         // rotor plus the reflected load, at the motor shaft
    double b_nm_s_per_rad = 0.0;  // viscous friction at the motor shaft
    double kt_nm_per_a = 0.0;     // = back-EMF constant, V s/rad
};

// Seed 002 §4.3 constants the derivation starts from.
inline constexpr double kFullDutyPulsesPerS = 2136.75;  // 39 counts x 12 us -> 468 us per pulse
inline constexpr double kDominantPolePerS = 74.29;      // Exp1 fit
inline constexpr double kSecondPolePerS = 163.6;        // Exp2 fit, b bounded to [-80, -70]
inline constexpr double kMotorSlots = 30.0;             // motor encoder disc (§2.3)
inline constexpr double kBridgeVolts = 22.0;            // 24 V supply - 2 V L298 drop (§2.3)

// second_pole_per_s empty: the first-order model (L = 1 mH); set: the motor with poles -74.29 and -that.
[[nodiscard]] DcMotorParams derive_motor(std::optional<double> second_pole_per_s = std::nullopt);

// The L298 (the datasheet's table, Table 2.1 of seed 002 §2.3): EN high with DIR1 != DIR2 drives, DIR1 == DIR2
// brakes (both lower or both upper switches short the motor), EN low lets it run free: the current decays through
// the flyback diodes into the supply (fast decay) and stays 0 once it reaches 0.
enum class BridgeMode { Drive, Brake, Coast };

struct DcMotorState {
    double omega_rad_per_s = 0.0;
    double current_a = 0.0;
    double angle_rad = 0.0;  // motor shaft, from the start
};

class DcMotor {
public:
    explicit DcMotor(const DcMotorParams& p) : m_p(p) {}

    // Runs dt_s with the bridge in `mode`; in Drive the terminals see drive_volts (sign = direction). The load
    // torque at the motor shaft opposes the motion (smoothed over 1 rad/s, so that it never pushes a stopped
    // shaft); supply_volts + 2 diode drops is the terminal voltage while coasting current decays.
    void advance(double dt_s, BridgeMode mode, double drive_volts, double load_torque_nm);

    [[nodiscard]] const DcMotorState& state() const { return m_s; }
    [[nodiscard]] const DcMotorParams& params() const { return m_p; }

private:
    [[nodiscard]] double terminal_volts(BridgeMode mode, double drive_volts, double current_a) const;

    DcMotorParams m_p;
    DcMotorState m_s;
};

}  // namespace cnc::lathe
