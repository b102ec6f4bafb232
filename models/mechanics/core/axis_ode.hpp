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
#include "mechanics/core/hybrid_stepper.hpp"

namespace cnc::mech {

using AxisState = Eigen::Matrix<double, 6, 1>;
enum AxisStateIndex { kIa = 0, kIb = 1, kTheta = 2, kOmega = 3, kX = 4, kV = 5 };

struct AxisParams {
    DriverElectrics driver;
    HybridStepperParams motor;
    AxisLoadParams load;
};

struct AxisSetpoints {
    WindingSetpoints current;
    double external_torque_nm = 0.0;  // a torque applied to the shaft from outside (tests, load studies)
};

class AxisOde {
public:
    explicit AxisOde(const AxisParams& params);

    void operator()(const AxisState& x, AxisState& dxdt, double t_s) const;
    void set_setpoints(const AxisSetpoints& sp) { m_sp = sp; }
    [[nodiscard]] const AxisSetpoints& setpoints() const { return m_sp; }
    [[nodiscard]] const AxisParams& params() const { return m_p; }
    // Per winding (a, b), whether its bridge regulates the current (drv8825_current.hpp), and the earliest
    // time at which one at +-VMOT regulates again, estimated from the currents' rates of change in dxdt.
    struct Bridges {
        std::array<bool, 2> regulate;
        double time_to_regulation_s;  // infinity if no ramping current approaches its set-point
    };
    [[nodiscard]] Bridges bridges(const AxisState& x, const AxisState& dxdt) const;
    // The rate at which a regulated winding's current error decays, 1/s.
    [[nodiscard]] double regulation_rate_per_s() const;
    // Kinetic energy of rotor and carriage plus the energy in the coupling and the detent, J (the winding
    // inductances' energy is not included: the energy check runs with the windings off).
    [[nodiscard]] double mechanical_energy_j(const AxisState& x) const;

private:
    AxisParams m_p;
    AxisSetpoints m_sp;
};

}  // namespace cnc::mech
