#include "scenario/mechanics_settings.hpp"

#include <cmath>

#include "mechanics/core/drv8825_current.hpp"

namespace cnc::sim {

namespace {

constexpr double kNmPerGcm = 9.80665e-5;  // 1 g cm = 9.80665e-5 N m
constexpr double kKgm2PerGcm2 = 1e-7;

void read_load(KeyReader& r, const std::string& axis, mech::AxisLoadParams& l, double mass_default_kg,
               const std::string& mass_source, double friction_default_n) {
    const std::string p = "mechanics." + axis + ".";
    l.carriage_mass_kg = r.get_float(p + "carriage_mass_kg", mass_default_kg, 1e-3, 1e4,
                                     "mass the axis motor moves, kg (" + mass_source + "; dynamic model)");
    l.rail_friction_n = r.get_float(p + "rail_friction_n", friction_default_n, 0.0, 1e4,
                                    "rail (linear bearing) Coulomb friction, N (estimate: about 0.04 x m g for "
                                    "bushings on rods; dynamic model)");
    l.rail_viscous_n_per_m_s = r.get_float(p + "rail_viscous_n_s_per_m", l.rail_viscous_n_per_m_s, 0.0, 1e6,
                                           "rail viscous friction, N s/m (dynamic model)");
    l.belt_specific_stiffness_n = r.get_float(
        p + "belt_specific_stiffness_n", l.belt_specific_stiffness_n, 1.0, 1e8,
        "belt specific stiffness c_sp = E A, N per unit strain; span stiffness = c_sp / length (order of 6 mm "
        "glass-fibre GT2 makers' tables; dynamic model)");
    l.belt_total_span_mm = r.get_float(p + "belt_total_span_mm", l.belt_total_span_mm, 1.0, 1e5,
                                       "free length of both belt spans together, mm (seed 000 sec. 7.1.2: 460 mm "
                                       "travel, plus 100 mm to pulley and idler; dynamic model)");
    l.belt_home_span_mm = r.get_float(p + "belt_home_span_mm", l.belt_home_span_mm, 1.0, 1e5,
                                      "belt span from the motor pulley to the carriage at 0 mm, mm (dynamic model)");
    l.belt_damping_ratio = r.get_float(p + "belt_damping_ratio", l.belt_damping_ratio, 0.0, 10.0,
                                       "belt damping as a fraction of the carriage-on-belt critical damping "
                                       "(estimate for reinforced rubber belts; dynamic model)");
    l.screw_efficiency = r.get_float(p + "screw_efficiency", l.screw_efficiency, 0.01, 1.0,
                                     "leadscrew efficiency, 0..1 (Tr8 screw with a plastic or bronze nut; dynamic "
                                     "model)");
    l.backlash_mm = r.get_float(p + "backlash_mm", l.backlash_mm, 0.0, 100.0,
                                "leadscrew axial play, mm (anti-backlash nut: ~0; dynamic model)");
    l.screw_stiffness_n_per_m =
        1e6 * r.get_float(p + "screw_stiffness_n_per_um", l.screw_stiffness_n_per_m * 1e-6, 1e-3, 1e6,
                          "leadscrew and nut axial stiffness, N/um (estimate for an 8 mm "
                          "screw; dynamic model)");
    l.screw_damping_ratio = r.get_float(p + "screw_damping_ratio", l.screw_damping_ratio, 0.0, 10.0,
                                        "leadscrew contact damping as a fraction of critical (dynamic model)");
}

}  // namespace

void read_mechanics_settings(KeyReader& r, MechanicsSettings& s) {
    s.model = r.get_choice("mechanics.model", "dynamic", {"ideal", "dynamic"},
                           "ideal: the carriage moves exactly one microstep per step (exact step-count studies); "
                           "dynamic: DRV8825 currents, hybrid stepper, belt or screw and carriage integrated "
                           "(docs/mechanics.md)") == "dynamic"
                  ? MechanicsModel::Dynamic
                  : MechanicsModel::Ideal;
    s.sample_hz = r.get_float("mechanics.sample_hz", s.sample_hz, 1.0, 1e6,
                              "dynamic model: tool samples per second for the metrics, besides one at every step");
    s.worker_thread = r.get_bool("mechanics.worker_thread", s.worker_thread,
                                 "dynamic model: integrate each axis on a thread of its own, beside the simulation "
                                 "(the same results; not with --vcd, which traces the carriage from the simulation)");
    s.tolerances.abs_tol = r.get_float("mechanics.abs_tol", s.tolerances.abs_tol, 1e-15, 1e-2,
                                       "dynamic model: absolute error per integration step (A, rad, rad/s, m, m/s)");
    s.tolerances.rel_tol = r.get_float("mechanics.rel_tol", s.tolerances.rel_tol, 1e-15, 1e-2,
                                       "dynamic model: relative error per integration step");
    s.tolerances.max_step_s = 1e-6 * r.get_float("mechanics.max_step_us", s.tolerances.max_step_s * 1e6, 1.0, 1e6,
                                                 "dynamic model: longest integration step, us");

    s.driver.supply_v = r.get_float("driver.supply_v", s.driver.supply_v, 1.0, 45.0,
                                    "DRV8825 VMOT, V (seed 000 sec. 2.3: 12 V; the chip allows 8.2 .. 45 V)");
    const double limit_a = r.get_float("driver.current_limit_a", s.driver.current_limit_a, 0.0, 2.5,
                                       "full-scale phase current, A (seed 000 sec. 2.3: the motor's rated 0.4 A; "
                                       "DRV8825 max 2.5 A); ignored when driver.vref_v is set");
    const double vref_v = r.get_float("driver.vref_v", 0.0, 0.0, 3.3,
                                      "VREF, V: sets the current limit to VREF / (5 R_SENSE) (SLVSA73 sec. 8.3.4); "
                                      "0: use driver.current_limit_a");
    const double r_sense = r.get_float("driver.r_sense_ohm", 0.1, 0.001, 10.0,
                                       "current-sense resistors, ohm (Pololu DRV8825 carrier: 0.1)");
    s.driver.current_limit_a = vref_v > 0.0 ? mech::current_limit_from_vref_a(vref_v, r_sense) : limit_a;
    if (s.driver.current_limit_a > 2.5) r.fail("driver.vref_v", "gives more than the DRV8825's 2.5 A");
    s.driver.chop_tau_s = 1e-6 * r.get_float("driver.chop_tau_us", s.driver.chop_tau_s * 1e6, 0.1, 1e4,
                                             "averaging time of the current chopper, us (a few PWM periods; "
                                             "docs/mechanics.md)");

    mech::HybridStepperParams& m = s.motor;
    m.holding_torque_nm = kNmPerGcm * r.get_float("motor.holding_torque_gcm", m.holding_torque_nm / kNmPerGcm, 1.0, 1e7,
                                                  "holding torque, g cm, both phases at the rated current "
                                                  "(42BYGHW208: 2800, seed 000 sec. 2.3)");
    m.rated_current_a =
        r.get_float("motor.rated_current_a", m.rated_current_a, 0.01, 20.0, "rated phase current, A (42BYGHW208: 0.4)");
    m.resistance_ohm = r.get_float("motor.resistance_ohm", m.resistance_ohm, 0.01, 1000.0,
                                   "phase resistance, ohm (42BYGHW208: 30, Wantai listing)");
    m.inductance_h = 1e-3 * r.get_float("motor.inductance_mh", m.inductance_h * 1e3, 0.01, 1000.0,
                                        "phase inductance, mH (42BYGHW208: 37, Wantai listing)");
    m.rotor_inertia_kgm2 =
        kKgm2PerGcm2 * r.get_float("motor.rotor_inertia_gcm2", m.rotor_inertia_kgm2 / kKgm2PerGcm2, 0.01, 1e6,
                                   "rotor inertia, g cm^2 (typical of 42 x 34 mm 1.8 deg motors)");
    m.detent_torque_nm = kNmPerGcm * r.get_float("motor.detent_torque_gcm", m.detent_torque_nm / kNmPerGcm, 0.0, 1e6,
                                                 "detent torque, g cm (typical of 42 x 34 mm 1.8 deg motors)");
    m.viscous_nm_per_rad_s = r.get_float("motor.viscous_nm_s_per_rad", m.viscous_nm_per_rad_s, 0.0, 10.0,
                                         "motor viscous damping, N m s/rad (estimate)");
    m.coulomb_nm = r.get_float("motor.coulomb_nm", m.coulomb_nm, 0.0, 10.0, "motor bearing friction, N m (estimate)");

    // seed 000 sec. 2.3: X moves both X carriages, the Y carriage, the connecting shaft and the Y belt, 3.8 kg.
    read_load(r, "x", s.x, 3.8, "seed 000 sec. 2.3: 3.8 kg", 1.5);
    // Y moves only the Y carriage with the 2.5 W laser module: our estimate of 0.8 kg (plate, bearings,
    // belt clamp, module); the seed gives no figure.
    read_load(r, "y", s.y, 0.8, "Y carriage and laser: our estimate, the seed gives none", 0.3);
}

mech::AxisParams axis_params(const MechanicsSettings& settings, const host::AxisMachine& axis,
                             const mech::AxisLoadParams& load) {
    mech::AxisParams p;
    p.driver = settings.driver;
    p.motor = settings.motor;
    p.motor.rotor_teeth = static_cast<int>(std::lround(90.0 / axis.step_angle_deg));  // 90 electrical deg a step
    p.load = load;
    p.load.kind = axis.transmission == host::Transmission::Leadscrew && !axis.calibrated_steps_per_mm
                      ? mech::DriveKind::Leadscrew
                      : mech::DriveKind::Belt;
    p.load.travel_per_rev_mm = axis.travel_per_motor_rev_mm();
    return p;
}

}  // namespace cnc::sim
