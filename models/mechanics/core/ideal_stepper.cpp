#include "mechanics/core/ideal_stepper.hpp"

#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

IdealStepper::IdealStepper(double step_angle_deg) : m_step_angle_deg(step_angle_deg) {
    if (!(step_angle_deg > 0.0))
        throw BadInput("", "motor step angle must be > 0 deg (got " + std::to_string(step_angle_deg) + ")");
}

void IdealStepper::on_microstep(TimePs, std::int64_t microstep_index, int microsteps_per_full_step) {
    m_angle_deg = static_cast<double>(microstep_index) * m_step_angle_deg / microsteps_per_full_step;
}

double IdealStepper::shaft_angle_deg(TimePs) const {
    return m_angle_deg;
}

}  // namespace cnc::mech
