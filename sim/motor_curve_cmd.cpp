#include "motor_curve_cmd.hpp"

#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "mechanics/core/motor_curve.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

namespace {

constexpr int kRatePoints = 16;
constexpr double kRateSpanOfMaxVelocity = 2.0;  // the table runs to twice the axis velocity limit
constexpr double kPullInSearchOfMaxVelocity = 4.0;

Scenario load(const std::string& scenario_path, const std::string& machine_path, const std::vector<std::string>& sets) {
    if (!scenario_path.empty() && !machine_path.empty()) {
        throw BadInput("--machine " + machine_path,
                       "goes without a scenario: " + scenario_path + " names its machine file as scenario.machine");
    }
    if (!machine_path.empty()) return load_machine(machine_path, sets);
    if (scenario_path.empty()) throw BadInput("motor-curve", "give a scenario, or --machine MACHINE.toml");
    return load_scenario(scenario_path, sets);
}

}  // namespace

int cmd_motor_curve(const std::string& scenario_path, const std::string& machine_path,
                    const std::vector<std::string>& sets, const std::string& axis, const std::string& csv_path,
                    std::ostream& out) {
    const Scenario s = load(scenario_path, machine_path, sets);
    const host::AxisMachine& m = axis == "x" ? s.machine.x : s.machine.y;
    const mech::AxisParams p = axis_params(s.mechanics, m, axis == "x" ? s.mechanics.x : s.mechanics.y);
    const double full_steps_per_mm = 360.0 / m.step_angle_deg / m.travel_per_motor_rev_mm();
    const double max_rate = m.limits.max_velocity_mm_per_s * full_steps_per_mm;
    const double accel_nm = mech::acceleration_torque_nm(p, m.limits.max_accel_mm_per_s2);

    std::optional<OutputFile> csv_file;
    if (!csv_path.empty()) csv_file.emplace(csv_path, "--csv");
    std::ostringstream csv;
    csv << "full_steps_per_s,speed_mm_per_s,pull_out_torque_nm,required_torque_nm,required_torque_at_max_accel_nm\n";
    out << fmt::format(FMT_STRING("motor curve, axis {}: {:.3f} A at {:.1f} V, 1/{} step, {:.2f} kg, holding torque at "
                                  "this current {:.4f} N m\n"),
                       axis, p.driver.current_limit_a, p.driver.supply_v, m.microsteps, p.load.carriage_mass_kg,
                       p.motor.torque_constant_nm_per_a() * p.driver.current_limit_a);
    out << fmt::format(FMT_STRING("  steps/s    mm/s  pull-out N m  required N m  at {:.0f} mm/s2\n"),
                       m.limits.max_accel_mm_per_s2);
    for (int i = 1; i <= kRatePoints; ++i) {
        const double rate = max_rate * kRateSpanOfMaxVelocity * i / kRatePoints;
        const double pull_out = mech::pull_out_torque_nm(p, m.microsteps, rate);
        const double required = mech::required_torque_nm(p, rate);
        const double speed = rate / full_steps_per_mm;
        out << fmt::format(FMT_STRING("{:>9.1f} {:>7.2f} {:>13.4f} {:>13.4f} {:>13.4f}\n"), rate, speed, pull_out,
                           required, required + accel_nm);
        csv << fmt::format(FMT_STRING("{:.3f},{:.4f},{:.6f},{:.6f},{:.6f}\n"), rate, speed, pull_out, required,
                           required + accel_nm);
    }
    const double pull_in = mech::pull_in_rate(p, m.microsteps, max_rate * kPullInSearchOfMaxVelocity);
    out << fmt::format(FMT_STRING("pull-in (start-stop without a ramp, this load): {:.1f} full steps/s = {:.2f} mm/s = "
                                  "F{:.0f}\n"),
                       pull_in, pull_in / full_steps_per_mm, 60.0 * pull_in / full_steps_per_mm);
    if (csv_file) {
        csv_file->stream() << csv.str();
        csv_file->close();
        out << "csv: " << csv_path << "\n";
    }
    return 0;
}

}  // namespace cnc::sim
