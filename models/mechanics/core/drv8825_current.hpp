// DRV8825 current regulation (TI SLVSA73 §8.3.4 "Current Regulation", §8.3.2 "Microstepping Indexer"):
// the indexer position sets the two winding current set-points, and the bridges drive the windings towards
// them within the motor supply VMOT.
//
// The chip chops each bridge with a fixed off-time PWM; we average it: the bridge applies the voltage that
// would bring the current to its set-point within `chop_tau_s`, clamped to +-VMOT. Clamping at -VMOT as well
// as +VMOT means we assume the current can be driven down as fast as up (fast decay: the bridge reverses),
// which is what the data sheet's mixed decay does on a falling step of the sine table; slow decay alone
// would make falling currents lag more. EN off (nENBL high) sets both set-points to 0: the bridges drive
// the currents to zero and keep them there (no holding torque).
#pragma once
#include <cmath>
#include <cstdint>

namespace cnc::mech {

struct DriverElectrics {
    double current_limit_a = 0.4;  // 100 % of the sine table; seed 000 §2.3: the motor's rated 0.4 A/phase
    double supply_v = 12.0;        // VMOT: seed 000 §2.3 drives the motors at 12 V
    // Averaging time of the chopper: a few PWM periods (the DRV8825's fixed off-time is about 30 us;
    // SLVSA73 §7.6 tOFF). Shorter tracks the set-point more tightly and makes the ODE stiffer.
    double chop_tau_s = 20e-6;
};

// Full-scale current from the reference voltage: I = VREF / (5 x R_SENSE) (SLVSA73 §8.3.4, eq. 1; the
// factor 5 is the chip's current-sense amplifier gain).
[[nodiscard]] double current_limit_from_vref_a(double vref_v, double r_sense_ohm);

struct WindingSetpoints {
    double a_a = 0.0;  // winding A current set-point, A
    double b_a = 0.0;
};

// Set-points at indexer position `units` (1/32-step units, home = 0 -> 71 % / 71 %), scaled by the limit.
[[nodiscard]] WindingSetpoints winding_setpoints(std::int64_t units, const DriverElectrics& drv, bool enabled);

// What a winding's bridge does: it regulates (the voltage it wants is within +-VMOT) or sits at +VMOT or
// -VMOT. While it regulates, L di/dt = -(R + L / tau)(i - i_ref): the current error decays as
// exp(-regulation_rate t) whatever the rotor does.
enum class BridgeMode { Regulating, High, Low };

// The voltage that would bring the current to its set-point within tau: R i_ref + e + L (i_ref - i) / tau
// (`l_per_tau`: L / tau, which the equations of motion compute once).
inline double wanted_voltage_v(double i_ref_a, double i_a, double emf_v, double resistance_ohm, double l_per_tau_ohm) {
    return resistance_ohm * i_ref_a + emf_v + l_per_tau_ohm * (i_ref_a - i_a);
}
inline BridgeMode bridge_mode(double wanted_v, const DriverElectrics& drv) {
    if (wanted_v >= drv.supply_v) return BridgeMode::High;
    if (wanted_v <= -drv.supply_v) return BridgeMode::Low;
    return BridgeMode::Regulating;
}
// The bridge's voltage in a mode (the wanted voltage while it regulates).
inline double bridge_voltage_v(BridgeMode mode, double wanted_v, const DriverElectrics& drv) {
    switch (mode) {
        case BridgeMode::High:
            return drv.supply_v;
        case BridgeMode::Low:
            return -drv.supply_v;
        case BridgeMode::Regulating:
            break;
    }
    return wanted_v;
}
// How far inside `mode` the wanted voltage is, V: >= 0 while the bridge stays in it (> 0 for Regulating).
[[nodiscard]] inline double mode_margin_v(BridgeMode mode, double wanted_v, const DriverElectrics& drv) {
    switch (mode) {
        case BridgeMode::High:
            return wanted_v - drv.supply_v;
        case BridgeMode::Low:
            return -drv.supply_v - wanted_v;
        case BridgeMode::Regulating:
            break;
    }
    return drv.supply_v - std::abs(wanted_v);
}
// The averaged bridge voltage for one winding: the wanted voltage clamped to +-VMOT.
[[nodiscard]] double bridge_voltage_v(double i_ref_a, double i_a, double emf_v, double resistance_ohm,
                                      double inductance_h, const DriverElectrics& drv);
[[nodiscard]] double regulation_rate_per_s(double resistance_ohm, double inductance_h, const DriverElectrics& drv);

}  // namespace cnc::mech
