#include "run/machine.hpp"

#include <algorithm>

#include "mechanics/core/drv8825_modes.hpp"

namespace cnc::sim {

namespace {

std::unique_ptr<mech::Transmission> transmission_for(const host::AxisMachine& a) {
    // A calibrated steps/mm overrides the belt or screw keys, so the carriage must move by it too.
    if (a.calibrated_steps_per_mm) return std::make_unique<mech::CalibratedDrive>(a.travel_per_motor_rev_mm());
    if (a.transmission == host::Transmission::Belt) {
        return std::make_unique<mech::Belt>(a.pulley_teeth, a.belt_pitch_mm, a.gear_ratio);
    }
    return std::make_unique<mech::Leadscrew>(a.lead_mm, a.screw_starts, a.gear_ratio);
}

void wire(mech::Drv8825& drv, sc_core::sc_in<bool>& step, sc_core::sc_in<bool>& dir, sc_core::sc_in<bool>& n_enbl,
          ModeStraps& modes) {
    drv.step(step);
    drv.dir(dir);
    drv.n_enbl(n_enbl);
    drv.m0(modes.m0);
    drv.m1(modes.m1);
    drv.m2(modes.m2);
}

}  // namespace

AxisMechanics::AxisMechanics(const host::AxisMachine& axis, const MechanicsSettings& settings,
                             const mech::AxisLoadParams& load) {
    if (settings.model == MechanicsModel::Dynamic) {
        auto model = std::make_unique<mech::DynamicAxis>(axis_params(settings, axis, load), settings.tolerances);
        dynamic = model.get();
        motor = std::move(model);
        return;
    }
    motor = std::make_unique<mech::IdealStepper>(axis.step_angle_deg);
    transmission = transmission_for(axis);
    rigid = std::make_unique<mech::RigidDrive>(*motor, *transmission);
}

const mech::CarriageDrive& AxisMechanics::drive() const {
    return dynamic != nullptr ? static_cast<const mech::CarriageDrive&>(*dynamic) : *rigid;
}

ModeStraps::ModeStraps(int microsteps, const std::string& axis)
    : m0(("mode0_" + axis).c_str(), mech::mode_pins_for(microsteps).m0),
      m1(("mode1_" + axis).c_str(), mech::mode_pins_for(microsteps).m1),
      m2(("mode2_" + axis).c_str(), mech::mode_pins_for(microsteps).m2) {}

namespace {
// Each driver's STEP-input faults drawn apart from the other's.
mech::Drv8825Config on_line(mech::Drv8825Config c, std::uint64_t line) {
    c.fault_line = line;
    return c;
}
}  // namespace

Machine::Machine(const sc_core::sc_module_name& name, const host::MachineModel& model,
                 const mech::Drv8825Config& driver, geom::Vec2 origin_mm, const MechanicsSettings& mechanics,
                 bool positions_traced)
    : sc_module(name),
      step_x("step_x"),
      dir_x("dir_x"),
      n_enbl_x("n_enbl_x"),
      step_y("step_y"),
      dir_y("dir_y"),
      n_enbl_y("n_enbl_y"),
      laser("laser"),
      m_worker_thread(mechanics.model == MechanicsModel::Dynamic && mechanics.worker_thread && !positions_traced),
      m_modes_x(model.x.microsteps, "x"),
      m_modes_y(model.y.microsteps, "y"),
      m_axis_x(model.x, mechanics, mechanics.x),
      m_axis_y(model.y, mechanics, mechanics.y),
      m_worker_motor_x(m_worker_thread ? std::make_unique<mech::WorkerMotor>(m_carriage, 0) : nullptr),
      m_worker_motor_y(m_worker_thread ? std::make_unique<mech::WorkerMotor>(m_carriage, 1) : nullptr),
      m_drv_x("drv8825_x", on_line(driver, 0), m_worker_thread ? *m_worker_motor_x : *m_axis_x.motor),
      m_drv_y("drv8825_y", on_line(driver, 1), m_worker_thread ? *m_worker_motor_y : *m_axis_y.motor),
      m_carriage("carriage",
                 mech::CarriageConfig{
                     {&m_drv_x.step_event(), &m_axis_x.drive(), m_axis_x.motor.get(), &m_drv_x.enable_event()},
                     {&m_drv_y.step_event(), &m_axis_y.drive(), m_axis_y.motor.get(), &m_drv_y.enable_event()},
                     origin_mm,
                     mechanics.model == MechanicsModel::Dynamic ? mechanics.sample_hz : 0.0,
                     m_worker_thread}),
      m_head("laser_head") {
    wire(m_drv_x, step_x, dir_x, n_enbl_x, m_modes_x);
    wire(m_drv_y, step_y, dir_y, n_enbl_y, m_modes_y);
    m_head.laser(laser);
}

void Machine::finish_mechanics(SimulationEnd& end, TimePs limit_ps, bool runs_to_time) {
    // Slices that run to their end stop the kernel before the events at their end (sc_start); a kernel that runs
    // until it starves takes every event up to the limit, those at the limit too.
    const std::optional<mech::MechanicsWorker::End> worker =
        runs_to_time ? m_carriage.finish(end.t_ps, false) : m_carriage.finish(limit_ps, true);
    if (!worker || runs_to_time) return;
    // The kernel stops at its last event: the later of the simulation's and the last periodic sample.
    if (worker->last_periodic_ps) end.t_ps = std::max(end.t_ps, *worker->last_periodic_ps);
    if (worker->periodic_past_bound) end.limit_reached = true;
}

std::vector<TracedReal> Machine::traced_positions() const {
    const bool sampled = m_axis_x.dynamic != nullptr;  // dynamic axes move between the samples written
    return {{&m_carriage.carriage_x_mm(), "carriage", sampled}, {&m_carriage.carriage_y_mm(), "carriage", sampled}};
}

void Machine::bind(MachinePins& pins) {
    step_x(pins.step_x);
    dir_x(pins.dir_x);
    n_enbl_x(pins.n_enbl_x);
    step_y(pins.step_y);
    dir_y(pins.dir_y);
    n_enbl_y(pins.n_enbl_y);
    laser(pins.laser);
}

}  // namespace cnc::sim
