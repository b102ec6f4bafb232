#include "architectures/lathe_sync/lathe_settings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "architectures/avr_board/avr_board_settings.hpp"
#include "lathe/core/keypad.hpp"
#include "lathe/core/ratio_list.hpp"

namespace cnc::sim {

namespace {

constexpr const char* kOperatorKey = "lathe.operator";

// "wait 2.5", "hold B 0.05" or keys ("131#00D").
OperatorStep parse_step(KeyReader& r, const std::string& text) {
    std::istringstream in(text);
    std::string word;
    in >> word;
    OperatorStep step;
    const auto number = [&](double& v) {
        if (!(in >> v) || !std::isfinite(v) || v < 0.0 || v > 1e5) {
            r.fail(kOperatorKey, "'" + text + "': expected a time in seconds, 0 .. 100000");
        }
    };
    if (word == "wait") {
        number(step.wait_s);
    } else if (word == "hold") {
        std::string key;
        in >> key;
        if (key.size() != 1 || !lathe::keypad_has(key[0])) {
            r.fail(kOperatorKey,
                   "'" + text + "': '" + key + "' is not a key of the 4x4 keypad (" + lathe::keypad_keys() + ")");
        }
        step.held = key[0];
        number(step.hold_s);
    } else {
        for (const char k : word) {
            if (!lathe::keypad_has(k)) {
                r.fail(kOperatorKey, "'" + text + "': '" + std::string(1, k) + "' is not a key of the 4x4 keypad (" +
                                         lathe::keypad_keys() +
                                         "); steps are keys, \"wait <s>\" or \"hold <key> <s>\"");
            }
        }
        step.keys = word;
    }
    std::string rest;
    if (in >> rest) r.fail(kOperatorKey, "'" + text + "': unexpected '" + rest + "'");
    return step;
}

std::string centi_text(int centi) {
    return std::to_string(centi / 100) + "#" + (centi % 100 < 10 ? "0" : "") + std::to_string(centi % 100);
}

}  // namespace

std::vector<OperatorStep> default_operator_script(const LatheSettings& s) {
    if (s.mode == "tuning") return {{"", 'B', 0.05, 0.0}, {"", 0, 0.0, 12.0}};
    const double pitch_mm = s.pitch_centi_mm / 100.0;
    const double length_mm = s.length_centi_mm / 100.0;
    // The carriage at most at the motor's full speed, 8.70 mm/s (2.739 leadscrew rev/s, seed 002 §4.3); one
    // revolution waiting for the index, the 500 ms brake and the slip shown 1 s (§2.5.3), 10 % and 0.5 s to spare.
    const double feed_mm_per_s = std::min(pitch_mm * s.spindle_rpm / 60.0, 8.7);
    const double cut_s = 60.0 / s.spindle_rpm + 1.1 * length_mm / feed_mm_per_s + 2.0;
    // The retract: full speed, the last 6.35 mm at PWM_SLOW = 58.7 % (§2.5.3), the brake.
    const double retract_s = length_mm / 5.1 + 1.5;
    // Menu "1: cut", then "1:coarse 2:fine 3:thread" (3 asks the pitch), the hand, the length (§2.5.3).
    const std::string cut = s.mode == "thread" ? "13" + centi_text(s.pitch_centi_mm) + "D"
                            : s.mode == "fine" ? "12"
                                               : "11";
    const std::string setup = cut + (s.right_hand ? "1" : "2") + centi_text(s.length_centi_mm) + "D";
    std::vector<OperatorStep> steps = {{"", 0, 0.0, 0.3}, {setup, 0, 0.0, 0.0}};
    for (int p = 0; p < s.passes; ++p) {
        steps.push_back({"D", 0, 0.0, 0.0});
        steps.push_back({"", 0, 0.0, cut_s});
        steps.push_back({"D", 0, 0.0, 0.0});
        steps.push_back({"", 0, 0.0, retract_s});
    }
    return steps;
}

// seed 002 §2.5.3 runs the ATmega16 at F_CPU = 8 MHz and does not say from which source; we take a crystal.
constexpr OscillatorPart kAtmega16Crystal{
    "lathe", "8 MHz crystal of the ATmega16 (seed 002 names no clock source)",
    30.0,    "the common +-30 ppm grade of HC-49 crystals",
    5.0,     "no crystal data sheet gives it: our estimate of the phase jitter on the AVR's Pierce oscillator"};

void read_lathe_settings(KeyReader& r, LatheSettings& s) {
    read_oscillator_settings(r, kAtmega16Crystal, 8'000'000, s.clock);  // seed 002 §2.5.3 F_CPU
    s.fast_forward = read_fast_forward(r, "lathe.fast_forward");
    s.mode = r.get_choice("lathe.mode", s.mode, {"thread", "fine", "coarse", "tuning"},
                          "lathe-sync: what the machinist does (seed 002 §2.5.2): cut a thread of lathe.pitch_mm, "
                          "the fine (0.04 mm) or coarse (0.08 mm) feed, or power up with B held (tuning mode)");
    const double pitch_mm = r.get_float(
        "lathe.pitch_mm", 1.0, 0.0, 655.35,
        "lathe-sync: thread pitch entered on the keypad, mm, 2 decimals, 0.01 .. 41.51 (the list's uint8 entries, "
        "seed 002 §2.5.3)");
    s.pitch_centi_mm = static_cast<int>(std::lround(pitch_mm * 100.0));
    if (std::abs(pitch_mm * 100.0 - s.pitch_centi_mm) > 1e-6) {
        r.fail("lathe.pitch_mm", "the keypad takes 2 decimals (0.01 mm steps)");
    }
    if (s.pitch_centi_mm == 0 || s.pitch_centi_mm > lathe::kMaxPitchCentiMm) {
        r.fail("lathe.pitch_mm",
               "must be 0.01 .. 41.51 mm: above, B(n) passes the list's 8-bit entries (255 "
               "motor pulses per spindle pulse, seed 002 §2.5.3); 0 cuts nothing");
    }
    if (s.mode == "fine") s.pitch_centi_mm = 4;
    if (s.mode == "coarse") s.pitch_centi_mm = 8;
    s.spindle_rpm = r.get_float("lathe.spindle_rpm", s.spindle_rpm, 0.0, 3000.0,
                                "lathe-sync: spindle speed, rpm, > 0 (turned by the lathe's own motor; the "
                                "leadscrew motor follows up to about 522 rpm at 1 mm, from seed 002 §4.3)");
    if (s.spindle_rpm <= 0.0) r.fail("lathe.spindle_rpm", "0 rpm: the spindle must turn for the firmware to follow");
    const double length_mm = r.get_float("lathe.length_mm", 10.0, 0.01, 655.35,
                                         "lathe-sync: length of the cut, mm, 2 decimals (the keypad's uint16 x 100)");
    s.length_centi_mm = static_cast<int>(std::lround(length_mm * 100.0));
    s.passes = static_cast<int>(r.get_int("lathe.passes", s.passes, 1, 50,
                                          "lathe-sync: cutting passes (cut, "
                                          "retract, cut, ...)"));
    s.right_hand = r.get_choice("lathe.hand", "right", {"right", "left"},
                                "lathe-sync: thread hand, key 1 or 2 at \"1:Right handed 2:Left handed\"") == "right";
    s.as_printed_list =
        r.get_choice("lathe.ratio_list", "intended", {"intended", "as-printed"},
                     "lathe-sync: makelist's search: the smallest |residual| for a list of <= 150 "
                     "entries, or the listing as printed with its defects (seed 002 §2.5.3)") == "as-printed";
    s.atomic_pulse_isrs =
        r.get_choice("lathe.pulse_isrs", "nested", {"nested", "atomic"},
                     "lathe-sync: the INT0/INT1 pulse ISRs: nested as the seed's ISR_NOBLOCK (§2.5.3; "
                     "their count races shift the helix), or run with interrupts off") == "atomic";
    if (s.as_printed_list && s.atomic_pulse_isrs) {
        r.fail("lathe.pulse_isrs", "'atomic' is built with the intended list only (lathe.ratio_list = intended)");
    }
    s.settle_revolutions = static_cast<int>(
        r.get_int("lathe.settle_revolutions", s.settle_revolutions, 0, 1000,
                  "lathe-sync: spindle revolutions at the start of each pass left out of the pitch and phase errors "
                  "(the catch-up from the slip); the report gives the whole-pass phase error too"));
    s.second_pole_per_s = r.get_float("lathe.motor.second_pole_per_s", 0.0, 0.0, 1e4,
                                      "lathe-sync: 0: the first-order motor of seed 002 §4.3 (pole -74.29 s^-1); "
                                      "else the two-pole motor, e.g. 163.6 (the Exp2 fit), s^-1");
    if (s.second_pole_per_s != 0.0 && s.second_pole_per_s <= 74.29) {
        r.fail("lathe.motor.second_pole_per_s", "must be 0 or above the dominant pole, 74.29 s^-1");
    }
    s.backlash_mm = r.get_float("lathe.backlash_mm", 0.0, 0.0, 5.0,
                                "lathe-sync: play of gearbox, belt and nut at the carriage, mm (seed 002 §4.2.1: "
                                "size unknown)");
    s.cut_depth_mm = r.get_float("lathe.cut.depth_mm", s.cut_depth_mm, 0.0, 10.0,
                                 "lathe-sync: depth of cut of every pass, mm; with the feed per revolution (the "
                                 "pitch) it makes the chip area; 0: no cutting load on the spindle (e.g. 0.1: a "
                                 "roughing pass of a thread)");
    s.cut_kc_n_per_mm2 = r.get_float("lathe.cut.kc_n_per_mm2", s.cut_kc_n_per_mm2, 0.0, 1e4,
                                     "lathe-sync: specific cutting force of the workpiece, N/mm^2 (about 2000 for "
                                     "mild steel, 800 for aluminium alloys)");
    s.workpiece_diameter_mm = r.get_float("lathe.cut.diameter_mm", s.workpiece_diameter_mm, 0.1, 500.0,
                                          "lathe-sync: workpiece diameter where the tool cuts, mm (the cutting "
                                          "force acts at its radius)");
    s.spindle_droop_pct_per_nm = r.get_float(
        "lathe.spindle.droop_pct_per_nm", s.spindle_droop_pct_per_nm, 0.0, 100.0,
        "lathe-sync: steady spindle speed loss per N m of cutting torque, % of lathe.spindle_rpm (the lathe's own "
        "motor has no speed control; default: a 0.37 kW induction motor, 5 % slip at 2.5 N m, through 1:4)");
    s.spindle_time_constant_s = r.get_float("lathe.spindle.time_constant_s", s.spindle_time_constant_s, 0.0, 10.0,
                                            "lathe-sync: time constant of the spindle speed's response to the "
                                            "cutting torque, s (motor and chuck inertia against the motor's "
                                            "torque-speed slope); 0: at once");
    const std::vector<std::string> script = r.get_string_list(
        kOperatorKey,
        "lathe-sync: what the machinist does, in turn: keys pressed (\"131#00D\": 100 ms each, 400 ms "
        "apart), \"wait <s>\", \"hold <key> <s>\"; keys of the 4x4 keypad 0-9 * # A B C D; empty: "
        "the script lathe.mode, pitch, hand, length and passes make");
    s.operator_steps.clear();
    for (const std::string& text : script) s.operator_steps.push_back(parse_step(r, text));
    if (s.operator_steps.empty()) s.operator_steps = default_operator_script(s);
}

}  // namespace cnc::sim
