// From the motor shaft to the carriage (seed 002 §2.3, §4.1, §4.2): the 1:26 gearbox, the 1:1 timing belt, the
// leadscrew (3.175 mm per revolution) and the backlash of all three lumped at the leadscrew: the screw (and the
// carriage) stays put while the gearbox output turns through the play, and is pushed once the play is taken up.
// The belt is taken as rigid (§4.2.2: "very stiff"); the carriage's mass is in the motor's reflected inertia.
#pragma once

namespace cnc::lathe {

struct DriveTrainParams {
    double gear_ratio = 26.0;  // motor revolutions per gearbox output revolution (§2.3)
    double belt_ratio = 1.0;   // gearbox output revolutions per leadscrew revolution (no reduction pulley, §4.1)
    double lead_mm = 3.175;    // leadscrew pitch (§2.5.3 LS_PITCH)
    double backlash_mm = 0.0;  // play at the carriage, all three sources together (§4.2.1 gives no size)
};

class DriveTrain {
public:
    explicit DriveTrain(const DriveTrainParams& p) : m_p(p) {}

    // Follows the motor to `motor_angle_rad` (from the start, where the play is centred) and returns the
    // carriage position, mm (positive = the motor's positive direction).
    double follow(double motor_angle_rad);
    [[nodiscard]] double carriage_mm() const { return m_carriage_mm; }
    // The carriage position the motor angle would give with no play.
    [[nodiscard]] double rigid_mm(double motor_angle_rad) const;
    // Carriage travel per motor revolution, play taken up.
    [[nodiscard]] double mm_per_motor_rev() const { return m_p.lead_mm / m_p.gear_ratio / m_p.belt_ratio; }

private:
    DriveTrainParams m_p;
    double m_carriage_mm = 0.0;
};

}  // namespace cnc::lathe
