#include "host/core/machine.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "common/bad_input.hpp"

namespace cnc::host {

namespace {

std::string number_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void require_positive(double value, const std::string& where, const char* key) {
    if (!(std::isfinite(value) && value > 0.0)) {
        throw BadInput(where, std::string(key) + " " + number_text(value) + " must be a finite number > 0");
    }
}

bool is_drv8825_microstep(int microsteps) {
    for (int m : {1, 2, 4, 8, 16, 32}) {  // seed 000 §2.3: DRV8825 M0..M2 table
        if (microsteps == m) return true;
    }
    return false;
}

}  // namespace

double AxisMachine::travel_per_rev_mm() const {
    return transmission == Transmission::Belt ? belt_pitch_mm * pulley_teeth : lead_mm * screw_starts;
}

double AxisMachine::transmission_steps_per_mm() const {
    return steps_per_rev() * gear_ratio / travel_per_rev_mm();
}

double AxisMachine::steps_per_mm() const {
    return calibrated_steps_per_mm.value_or(transmission_steps_per_mm());
}

double feed_within_axis_limits(double dx_mm, double dy_mm, double feed_mm_per_min, const MachineModel& machine) {
    constexpr double kSecondsPerMinute = 60.0;
    const double length_mm = std::hypot(dx_mm, dy_mm);
    double feed = feed_mm_per_min;
    if (length_mm <= 0.0) return feed;
    const std::pair<double, double> axes[] = {{dx_mm, machine.x.limits.max_velocity_mm_per_s},
                                              {dy_mm, machine.y.limits.max_velocity_mm_per_s}};
    for (const auto& [d_mm, v_max] : axes) {
        if (d_mm != 0.0) feed = std::min(feed, v_max * kSecondsPerMinute * length_mm / std::fabs(d_mm));
    }
    return feed;
}

void validate(const AxisMachine& axis, const std::string& where) {
    require_positive(axis.step_angle_deg, where, "step_angle_deg");
    if (axis.step_angle_deg > 360.0) {
        throw BadInput(where, "step_angle_deg " + number_text(axis.step_angle_deg) + " must be <= 360");
    }
    if (!is_drv8825_microstep(axis.microsteps)) {
        throw BadInput(where, "microsteps " + std::to_string(axis.microsteps) +
                                  " not supported (DRV8825 allows 1, 2, 4, 8, 16, 32)");
    }
    if (axis.transmission == Transmission::Belt) {
        if (axis.pulley_teeth <= 0) {
            throw BadInput(where, "pulley_teeth " + std::to_string(axis.pulley_teeth) + " must be > 0");
        }
        require_positive(axis.belt_pitch_mm, where, "belt_pitch_mm");
    } else {
        require_positive(axis.lead_mm, where, "lead_mm");
        if (axis.screw_starts <= 0) {
            throw BadInput(where, "screw_starts " + std::to_string(axis.screw_starts) + " must be >= 1");
        }
    }
    require_positive(axis.gear_ratio, where, "gear_ratio");
    if (axis.calibrated_steps_per_mm) require_positive(*axis.calibrated_steps_per_mm, where, "steps_per_mm");
    if (!(std::isfinite(axis.travel_mm) && axis.travel_mm >= 0.0)) {
        throw BadInput(where, "travel_mm " + number_text(axis.travel_mm) + " must be >= 0 (0 = unlimited)");
    }
}

void validate(const MachineModel& machine, const std::string& where) {
    validate(machine.x, where + " x");
    validate(machine.y, where + " y");
    validate(machine.z, where + " z");
}

}  // namespace cnc::host
