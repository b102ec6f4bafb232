// Scenario keys of the lathe-sync architecture (seed 002's electronic leadscrew), read into one struct by
// read_lathe_settings(): [lathe] for the cut the machinist makes and the plant, [lathe.operator] the keys pressed.
#pragma once
#include <string>
#include <vector>

#include "architectures/architecture.hpp"
#include "architectures/oscillator/oscillator_settings.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

// One operator action: keys pressed in turn (100 ms each, 400 ms apart), a key held for hold_s, or a wait.
struct OperatorStep {
    std::string keys;
    char held = 0;
    double hold_s = 0.0;
    double wait_s = 0.0;
};

struct LatheSettings final : ArchSettings {
    OscillatorSettings clock;     // the ATmega16's 8 MHz clock source
    bool fast_forward = true;     // lathe.fast_forward
    std::string mode = "thread";  // thread | fine | coarse | tuning (§2.5.2)
    int pitch_centi_mm = 100;     // the pitch entered, 0.01 mm (thread); fine 4, coarse 8
    double spindle_rpm = 60.0;
    int length_centi_mm = 1000;
    int passes = 3;
    bool right_hand = true;
    bool as_printed_list = false;    // makelist as printed (§2.5.3)
    bool atomic_pulse_isrs = false;  // PULSE_ISR_ATOMIC (control.c)
    int settle_revolutions = 2;
    double second_pole_per_s = 0.0;  // 0: the first-order motor
    double backlash_mm = 0.0;
    // The cutting load on the spindle (docs/metrics.md "Lathe": the estimates behind the defaults).
    double cut_depth_mm = 0.0;  // no load unless the scenario says how deep the tool cuts
    double cut_kc_n_per_mm2 = 2000.0;
    double workpiece_diameter_mm = 20.0;
    double spindle_droop_pct_per_nm = 0.5;
    double spindle_time_constant_s = 0.01;
    std::vector<OperatorStep> operator_steps;  // lathe.operator, or the script the keys above make
};

void read_lathe_settings(KeyReader& r, LatheSettings& settings);

// The operator script a machinist follows for mode, pitch, hand, length and passes (§2.5.2): keys and waits long
// enough for each cut and retract at the spindle speed.
[[nodiscard]] std::vector<OperatorStep> default_operator_script(const LatheSettings& s);

}  // namespace cnc::sim
