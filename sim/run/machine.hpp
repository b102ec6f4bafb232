// The machine every architecture drives: two DRV8825 drivers with their MODE pins strapped for the scenario's
// microstepping, the motors and what they move (mechanics.model: ideal steppers on rigid belt or leadscrew
// transmissions, or dynamic axis models), the XY carriage and the laser head.
#pragma once
#include <memory>
#include <string>

#include <systemc>

#include "host/core/machine.hpp"
#include "mechanics/carriage.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/dynamic_axis.hpp"
#include "mechanics/core/ideal_stepper.hpp"
#include "mechanics/core/transmission.hpp"
#include "mechanics/drv8825.hpp"
#include "mechanics/laser_head.hpp"
#include "probes/vcd_trace.hpp"
#include "run/simulate.hpp"
#include "scenario/mechanics_settings.hpp"

namespace cnc::sim {

// One axis's motor and what it moves: an ideal stepper on a rigid transmission, or a dynamic axis model.
struct AxisMechanics {
    AxisMechanics(const host::AxisMachine& axis, const MechanicsSettings& settings, const mech::AxisLoadParams& load);
    std::unique_ptr<mech::StepperMotor> motor;
    std::unique_ptr<mech::Transmission> transmission;
    std::unique_ptr<mech::CarriageDrive> rigid;
    const mech::DynamicAxis* dynamic = nullptr;  // the motor, when it is a dynamic model
    [[nodiscard]] const mech::CarriageDrive& drive() const;
};

// The wires between a controller and the machine, named as in every architecture (docs/architectures.md "Pins").
// A controller that drives no EN pin leaves nENBL low: the DRV8825s stay enabled.
struct MachinePins {
    sc_core::sc_signal<bool> step_x{"step_x", false}, dir_x{"dir_x", false};
    sc_core::sc_signal<bool> step_y{"step_y", false}, dir_y{"dir_y", false};
    sc_core::sc_signal<bool> n_enbl_x{"n_enbl_x", false}, n_enbl_y{"n_enbl_y", false};
    sc_core::sc_signal<bool> laser{"laser", false};
};

// MODE0..2 strapped on the driver board (seed 000: microstepping is set on the PCB, not by the FPGA; top.v, Π.1,
// drives no M0..M2).
struct ModeStraps {
    ModeStraps(int microsteps, const std::string& axis);
    sc_core::sc_signal<bool> m0, m1, m2;
};

class Machine : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> step_x, dir_x, n_enbl_x;
    sc_core::sc_in<bool> step_y, dir_y, n_enbl_y;
    sc_core::sc_in<bool> laser;

    // `positions_traced`: the run writes a VCD, which traces the carriage's position signals, so the dynamic axes
    // stay on the simulation's thread (mechanics.worker_thread).
    Machine(const sc_core::sc_module_name& name, const host::MachineModel& model, const mech::Drv8825Config& driver,
            geom::Vec2 origin_mm, const MechanicsSettings& mechanics, bool positions_traced);

    // Binds every input pin to the controller's wires.
    void bind(MachinePins& pins);

    [[nodiscard]] const mech::Carriage& carriage() const { return m_carriage; }
    [[nodiscard]] mech::Carriage& carriage() { return m_carriage; }
    [[nodiscard]] const mech::Drv8825& driver_x() const { return m_drv_x; }
    [[nodiscard]] const mech::Drv8825& driver_y() const { return m_drv_y; }
    [[nodiscard]] const mech::LaserHead& laser_head() const { return m_head; }
    // The carriage position per axis for the VCD, in the carriage's scope: carriage_x_mm, carriage_y_mm
    // (real-valued).
    [[nodiscard]] std::vector<TracedReal> traced_positions() const;
    // The simulation has stopped (simulate()'s `end`, with the run's time limit; `runs_to_time`: it was simulated
    // with a check period, in slices that run to their end). With the axes on the worker thread, the worker takes
    // its last periodic samples as the kernel would have (they kept the kernel running until both axes were at
    // rest, or to the limit), `end` becomes what the kernel would have said with them, and the axes may be read.
    // Call it before reading the carriage's last samples or the dynamic axes.
    void finish_mechanics(SimulationEnd& end, TimePs limit_ps, bool runs_to_time);
    // Whether the dynamic axes run on the carriage's worker thread.
    [[nodiscard]] bool mechanics_on_worker() const { return m_worker_thread; }
    // The dynamic axis models (nullptr with the ideal mechanics).
    [[nodiscard]] const mech::DynamicAxis* dynamic_x() const { return m_axis_x.dynamic; }
    [[nodiscard]] const mech::DynamicAxis* dynamic_y() const { return m_axis_y.dynamic; }

private:
    bool m_worker_thread;
    ModeStraps m_modes_x, m_modes_y;
    AxisMechanics m_axis_x, m_axis_y;
    // With the worker thread: the drivers' motors, which hand their calls to the carriage's worker.
    std::unique_ptr<mech::WorkerMotor> m_worker_motor_x, m_worker_motor_y;
    mech::Drv8825 m_drv_x, m_drv_y;
    mech::Carriage m_carriage;
    mech::LaserHead m_head;
};

}  // namespace cnc::sim
