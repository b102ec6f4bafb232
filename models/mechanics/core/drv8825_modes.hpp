// DRV8825 microstep modes and indexer (TI SLVSA73 "Microstepping Indexer").
//
// MODE2 MODE1 MODE0: 000 full, 001 1/2, 010 1/4, 011 1/8, 100 1/16, 101/110/111 1/32. The indexer walks a
// sine table of 1/32-step resolution: one full step = 90 electrical degrees, 1/32 step = 2.8125 degrees, home
// state = 45 degrees (71 % / 71 %). Positions here are counted in that finest unit (1/32 of a full step), with
// home = 0, so the valid states of mode m are the multiples of 32/m.
#pragma once
#include <cstdint>

namespace cnc::mech {

inline constexpr int kIndexerUnitsPerFullStep = 32;  // DRV8825: finest mode 1/32
inline constexpr double kElectricalDegPerFullStep = 90.0;
inline constexpr double kHomeElectricalDeg = 45.0;  // data sheet: home state 45 deg, 71 % on both windings

struct ModePins {
    bool m0 = false;
    bool m1 = false;
    bool m2 = false;
};

// Microsteps per full step for the MODE pin levels (the carrier's pull-downs make open pins full step).
[[nodiscard]] int microsteps_for(const ModePins& pins);
// The pin levels that select `microsteps` (the 101 code for 1/32); BadInput unless 1, 2, 4, 8, 16 or 32.
[[nodiscard]] ModePins mode_pins_for(int microsteps);

// Electrical degrees moved by one STEP pulse in this mode (90 / microsteps; 1/32 -> 2.8125).
[[nodiscard]] double electrical_step_deg(int microsteps);
// Electrical angle of indexer position `units` (1/32-step units, home = 0 -> 45 deg).
[[nodiscard]] double electrical_angle_deg(std::int64_t units);

// Winding currents in % of full scale at an indexer position: derived as 100 cos / 100 sin of the
// electrical angle, which reproduces the data sheet table (home 71/71, 1/32 steps 100/5, 100/10, 99/15 ...).
struct PhaseCurrents {
    double a_pct = 0.0;
    double b_pct = 0.0;
};
[[nodiscard]] PhaseCurrents phase_currents(std::int64_t units);

// Indexer position after one STEP in `microsteps` mode, in direction +1 / -1. From a valid state of the mode
// this is one step of 32/microsteps units; after a mode change mid-run the position may lie between the
// mode's states, and the indexer then "advances to the next valid state for the new step mode at the rising
// edge of STEP" (data sheet §8.3.5).
[[nodiscard]] std::int64_t next_indexer_position(std::int64_t units, int microsteps, int direction);

}  // namespace cnc::mech
