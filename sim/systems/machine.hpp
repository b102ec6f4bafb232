// The machine every architecture drives: two DRV8825 drivers with their MODE pins strapped for the scenario's
// microstepping, ideal steppers, belt or leadscrew transmissions, the XY carriage and the laser head.
#pragma once
#include <memory>
#include <string>

#include <systemc>

#include "host/core/machine.hpp"
#include "mechanics/carriage.hpp"
#include "mechanics/core/ideal_stepper.hpp"
#include "mechanics/core/transmission.hpp"
#include "mechanics/drv8825.hpp"
#include "mechanics/laser_head.hpp"

namespace cnc::sim {

// MODE0..2 strapped on the driver board (seed 000 §8: microstepping is set on the PCB, not by the FPGA).
struct ModeStraps {
    ModeStraps(int microsteps, const std::string& axis);
    sc_core::sc_signal<bool> m0, m1, m2;
};

class Machine : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> step_x, dir_x, n_enbl_x;
    sc_core::sc_in<bool> step_y, dir_y, n_enbl_y;
    sc_core::sc_in<bool> laser;

    Machine(const sc_core::sc_module_name& name, const host::MachineModel& model, const mech::Drv8825Config& driver,
            geom::Vec2 origin_mm);

    // Binds every input pin to the controller's wires (the same names in every architecture).
    void bind(sc_core::sc_signal<bool>& step_x_wire, sc_core::sc_signal<bool>& dir_x_wire,
              sc_core::sc_signal<bool>& n_enbl_x_wire, sc_core::sc_signal<bool>& step_y_wire,
              sc_core::sc_signal<bool>& dir_y_wire, sc_core::sc_signal<bool>& n_enbl_y_wire,
              sc_core::sc_signal<bool>& laser_wire);

    [[nodiscard]] const mech::Carriage& carriage() const { return m_carriage; }
    [[nodiscard]] const mech::Drv8825& driver_x() const { return m_drv_x; }
    [[nodiscard]] const mech::Drv8825& driver_y() const { return m_drv_y; }
    [[nodiscard]] const mech::LaserHead& laser_head() const { return m_head; }

private:
    ModeStraps m_modes_x, m_modes_y;
    mech::IdealStepper m_motor_x, m_motor_y;
    std::unique_ptr<mech::Transmission> m_drive_x, m_drive_y;
    mech::Drv8825 m_drv_x, m_drv_y;
    mech::Carriage m_carriage;
    mech::LaserHead m_head;
};

}  // namespace cnc::sim
