// The equations of motion of one axis: DRV8825 windings, hybrid stepper rotor and its load.
//
// State (Eigen, SI units): winding currents i_a, i_b (A), shaft angle theta (rad, 0 at the driver's home
// state), shaft speed omega (rad/s), carriage position x (m) and speed v (m/s).
//   L di/dt = v_bridge - R i - e                          (drv8825_current.hpp, hybrid_stepper.hpp)
//   J domega/dt = T_em + T_detent + T_coupling - B omega + T_coulomb + T_external   (friction.hpp)
//   m dv/dt = F_coupling + F_rail                          (axis_load.hpp)
// With DriveKind::Free the carriage states stay 0. The set-points are constant between events.
#pragma once
#include <array>

#include <Eigen/Core>

#include "mechanics/core/axis_load.hpp"
#include "mechanics/core/drv8825_current.hpp"
#include "mechanics/core/friction.hpp"
#include "mechanics/core/hybrid_stepper.hpp"

namespace cnc::mech {

using AxisState = Eigen::Matrix<double, 6, 1>;
enum AxisStateIndex { kIa = 0, kIb = 1, kTheta = 2, kOmega = 3, kX = 4, kV = 5 };

struct AxisParams {
    DriverElectrics driver;
    HybridStepperParams motor;
    AxisLoadParams load;
};

// The piecewise parts of the equations: each winding's bridge (drv8825_current.hpp) and each body's side of
// its friction's stick band (friction.hpp). Within one set of modes the equations are smooth in the state.
struct AxisModes {
    std::array<BridgeMode, 2> bridges{};  // windings a, b
    FrictionMode shaft = FrictionMode::Stuck;
    FrictionMode rail = FrictionMode::Stuck;
};

struct AxisSetpoints {
    WindingSetpoints current;
    double external_torque_nm = 0.0;  // a torque applied to the shaft from outside (tests, load studies)
};

class AxisOde {
public:
    explicit AxisOde(const AxisParams& params);

    // The equations of motion held in `modes`: smooth in the state, which the integrator's error control
    // needs; it ends a step where the modes change. `angle`: the rotor angle of x[kTheta] (hybrid_stepper.hpp).
    void derivative(const AxisState& x, AxisState& dxdt, const AxisModes& modes, RotorAngle angle) const;
    void set_setpoints(const AxisSetpoints& sp) { m_sp = sp; }
    [[nodiscard]] const AxisSetpoints& setpoints() const { return m_sp; }
    [[nodiscard]] const AxisParams& params() const { return m_p; }
    // The modes at state x (`angle`: its rotor angle).
    [[nodiscard]] AxisModes modes(const AxisState& x, RotorAngle angle) const;
    // How far inside `modes` the state x is, per part (bridges a, b, shaft, rail), as a fraction of VMOT or of
    // the stick band: < 0 once the part has left its mode.
    using ModeMargins = std::array<double, 4>;
    [[nodiscard]] ModeMargins mode_margins(const AxisState& x, const AxisModes& modes, RotorAngle angle) const;
    // The rate at which a regulated winding's current error decays, 1/s.
    [[nodiscard]] double regulation_rate_per_s() const { return m_rate_per_s; }
    // The shaft acceleration per ampere of torque-producing current, K_m / J, rad/(s2 A).
    [[nodiscard]] double alpha_per_a() const { return m_km_nm_per_a * m_inv_inertia_per_kgm2; }
    // Kinetic energy of rotor and carriage plus the energy in the coupling and the detent, J (the winding
    // inductances' energy is not included: the energy check runs with the windings off).
    [[nodiscard]] double mechanical_energy_j(const AxisState& x) const;

private:
    struct WantedVoltages;
    // The voltage each winding's bridge wants at state x (drv8825_current.hpp), and the back-EMF it contains.
    [[nodiscard]] WantedVoltages wanted_voltages(const AxisState& x, RotorAngle angle) const;

    AxisParams m_p;
    AxisSetpoints m_sp;
    // What the equations need of the parameters, computed once: they run at every stage of every step.
    Coupling m_coupling;
    double m_km_nm_per_a;
    double m_l_per_tau_ohm;  // L / tau of the chopper's averaging (drv8825_current.hpp)
    double m_inv_inductance_per_h;
    double m_inv_inertia_per_kgm2;
    double m_inv_mass_per_kg;
    double m_rate_per_s;
};

}  // namespace cnc::mech
