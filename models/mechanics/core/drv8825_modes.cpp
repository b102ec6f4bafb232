#include "mechanics/core/drv8825_modes.hpp"

#include <cmath>
#include <string>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::mech {

namespace {

// Floor division for negative positions too.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if (q * b > a) --q;
    return q;
}

}  // namespace

int microsteps_for(const ModePins& pins) {
    const int code = (pins.m2 ? 4 : 0) | (pins.m1 ? 2 : 0) | (pins.m0 ? 1 : 0);
    return code >= 5 ? 32 : (1 << code);  // 000..100 -> 1..16; 101, 110, 111 -> 1/32
}

ModePins mode_pins_for(int microsteps) {
    switch (microsteps) {
        case 1:
            return {false, false, false};
        case 2:
            return {true, false, false};
        case 4:
            return {false, true, false};
        case 8:
            return {true, true, false};
        case 16:
            return {false, false, true};
        case 32:
            return {true, false, true};
        default:
            throw BadInput("",
                           "DRV8825 microsteps must be 1, 2, 4, 8, 16 or 32 (got " + std::to_string(microsteps) + ")");
    }
}

double electrical_step_deg(int microsteps) {
    return kElectricalDegPerFullStep / microsteps;
}

double electrical_angle_deg(std::int64_t units) {
    return kHomeElectricalDeg + static_cast<double>(units) * kElectricalDegPerFullStep / kIndexerUnitsPerFullStep;
}

PhaseCurrents phase_currents(std::int64_t units) {
    const double rad = electrical_angle_deg(units) * kPi / 180.0;
    return {100.0 * std::cos(rad), 100.0 * std::sin(rad)};
}

std::int64_t next_indexer_position(std::int64_t units, int microsteps, int direction) {
    const std::int64_t step = kIndexerUnitsPerFullStep / microsteps;
    if (direction > 0) return (floor_div(units, step) + 1) * step;
    return -(floor_div(-units, step) + 1) * step;  // mirror image: next valid state below
}

}  // namespace cnc::mech
