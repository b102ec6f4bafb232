// Scenario keys of the physical mechanics (docs/mechanics.md): which model drives the carriage ([mechanics] model,
// sample rate, integrator), the DRV8825's current regulation ([driver]), the motor ([motor], the same on both
// axes) and each axis's load ([mechanics.x], [mechanics.y]). read_mechanics_settings() reads them into one
// struct; axis_params() combines them with the machine's transmission into the axis model's parameters.
#pragma once
#include <string>

#include "host/core/machine.hpp"
#include "mechanics/core/axis_ode.hpp"
#include "mechanics/core/integrator_tolerances.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

enum class MechanicsModel { Ideal, Dynamic };

struct MechanicsSettings {
    MechanicsModel model = MechanicsModel::Dynamic;
    double sample_hz = 1000.0;  // tool samples between step events (dynamic model)
    bool worker_thread = true;  // dynamic model: the axes integrated on a thread of their own (mech::Carriage)
    mech::IntegratorTolerances tolerances;
    mech::DriverElectrics driver;
    mech::HybridStepperParams motor;
    mech::AxisLoadParams x;
    mech::AxisLoadParams y;
};

void read_mechanics_settings(KeyReader& r, MechanicsSettings& settings);

// The axis model for one machine axis: its transmission (belt or screw, travel per motor revolution) from
// the machine keys, its load from [mechanics.<axis>].
[[nodiscard]] mech::AxisParams axis_params(const MechanicsSettings& settings, const host::AxisMachine& axis,
                                           const mech::AxisLoadParams& load);

}  // namespace cnc::sim
