// Motor shaft angle -> carriage travel.
#pragma once

namespace cnc::mech {

class Transmission {
public:
    virtual ~Transmission() = default;
    // Carriage travel in mm for a motor shaft angle (0 deg -> 0 mm; linear, no backlash).
    [[nodiscard]] double carriage_mm(double shaft_angle_deg) const {
        return shaft_angle_deg / 360.0 * travel_per_motor_rev_mm();
    }
    [[nodiscard]] virtual double travel_per_motor_rev_mm() const = 0;
};

// Timing belt on a pulley: travel per pulley revolution = teeth x pitch (GT2 20T: 40 mm; seed 000 §3.4.2).
// gear_ratio: motor revolutions per pulley revolution (1 = pulley on the motor shaft).
class Belt : public Transmission {
public:
    Belt(int pulley_teeth, double belt_pitch_mm, double gear_ratio = 1.0);
    [[nodiscard]] double travel_per_motor_rev_mm() const override;

private:
    int m_teeth;
    double m_pitch_mm;
    double m_gear_ratio;
};

// Leadscrew: travel per screw revolution = the lead = thread pitch x starts (seed 000 §3.4.2 gives the belt
// formula only). A Tr8x8 screw is pitch 2 mm x 4 starts = 8 mm per revolution.
// gear_ratio: motor revolutions per screw revolution.
class Leadscrew : public Transmission {
public:
    Leadscrew(double thread_pitch_mm, int starts = 1, double gear_ratio = 1.0);
    [[nodiscard]] double travel_per_motor_rev_mm() const override;

private:
    double m_pitch_mm;
    int m_starts;
    double m_gear_ratio;
};

// A drive known only by its travel per motor revolution: the machine is given by a calibrated steps/mm
// (machine.x.steps_per_mm) and its belt or screw is not described.
class CalibratedDrive : public Transmission {
public:
    explicit CalibratedDrive(double travel_per_motor_rev_mm);
    [[nodiscard]] double travel_per_motor_rev_mm() const override { return m_travel_mm; }

private:
    double m_travel_mm;
};

}  // namespace cnc::mech
