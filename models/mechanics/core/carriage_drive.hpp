// Where one axis puts the carriage at a time: the view the carriage's position sampler has of an axis,
// whether the motor is ideal and rigidly coupled or a dynamic model with its own carriage state.
#pragma once
#include "common/units.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/transmission.hpp"

namespace cnc::mech {

class CarriageDrive {
public:
    virtual ~CarriageDrive() = default;
    // Carriage travel from 0, mm, at t (non-decreasing times, as for StepperMotor).
    [[nodiscard]] virtual double carriage_mm(TimePs t_ps) const = 0;
    // Whether the axis has come to rest: a sampler need not sample it again until it is commanded.
    [[nodiscard]] virtual bool at_rest() const { return true; }
};

// A motor through a rigid, backlash-free transmission (the ideal mechanics).
class RigidDrive : public CarriageDrive {
public:
    RigidDrive(const StepperMotor& motor, const Transmission& transmission)
        : m_motor(motor), m_transmission(transmission) {}
    [[nodiscard]] double carriage_mm(TimePs t_ps) const override {
        return m_transmission.carriage_mm(m_motor.shaft_angle_deg(t_ps));
    }

private:
    const StepperMotor& m_motor;
    const Transmission& m_transmission;
};

}  // namespace cnc::mech
