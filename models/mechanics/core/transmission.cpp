#include "mechanics/core/transmission.hpp"

#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

namespace {

void require_positive(double v, const char* what) {
    if (!(v > 0.0)) throw BadInput("", std::string(what) + " must be > 0 (got " + std::to_string(v) + ")");
}

}  // namespace

Belt::Belt(int pulley_teeth, double belt_pitch_mm, double gear_ratio)
    : m_teeth(pulley_teeth), m_pitch_mm(belt_pitch_mm), m_gear_ratio(gear_ratio) {
    require_positive(pulley_teeth, "pulley_teeth");
    require_positive(belt_pitch_mm, "belt_pitch_mm");
    require_positive(gear_ratio, "gear_ratio");
}

double Belt::travel_per_motor_rev_mm() const {
    return m_teeth * m_pitch_mm / m_gear_ratio;
}

Leadscrew::Leadscrew(double thread_pitch_mm, int starts, double gear_ratio)
    : m_pitch_mm(thread_pitch_mm), m_starts(starts), m_gear_ratio(gear_ratio) {
    require_positive(thread_pitch_mm, "screw pitch_mm");
    require_positive(starts, "screw starts");
    require_positive(gear_ratio, "gear_ratio");
}

double Leadscrew::travel_per_motor_rev_mm() const {
    return m_pitch_mm * m_starts / m_gear_ratio;
}

CalibratedDrive::CalibratedDrive(double travel_per_motor_rev_mm) : m_travel_mm(travel_per_motor_rev_mm) {
    require_positive(travel_per_motor_rev_mm, "travel per motor revolution");
}

}  // namespace cnc::mech
