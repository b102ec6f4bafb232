#include "lathe/core/drive_train.hpp"

#include <algorithm>

namespace cnc::lathe {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

double DriveTrain::rigid_mm(double motor_angle_rad) const {
    return motor_angle_rad / kTwoPi * mm_per_motor_rev();
}

double DriveTrain::follow(double motor_angle_rad) {
    const double driven = rigid_mm(motor_angle_rad);
    const double half_play = 0.5 * m_p.backlash_mm;
    m_carriage_mm = std::clamp(m_carriage_mm, driven - half_play, driven + half_play);
    return m_carriage_mm;
}

}  // namespace cnc::lathe
