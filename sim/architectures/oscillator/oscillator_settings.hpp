// The clock source of a controller's board as a part with a tolerance: the keys clock.ideal and clock.offset_ppm
// (every architecture's) and <table>.clock_tolerance_ppm and <table>.clock_jitter_rms_ps (its own part's, with
// that part's data-sheet defaults), read by one reader for every architecture that has a clock; and what the
// report says about it.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "common/clock_grid.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

// The part an architecture's board clocks its logic from, and where its figures come from.
struct OscillatorPart {
    const char* table;           // the architecture's key table: "fpga" reads fpga.clock_tolerance_ppm
    const char* name;            // "16 MHz ceramic resonator (Murata CSTCE16M0V53-R0)"
    double tolerance_ppm;        // the part's initial frequency tolerance, +-
    const char* tolerance_from;  // its source
    double jitter_rms_ps;        // rms phase jitter of its edges
    const char* jitter_from;     // its source
};

struct OscillatorSettings {
    std::string part;   // OscillatorPart::name
    std::string table;  // OscillatorPart::table: each part draws its own offset from the seed
    bool ideal = false;
    double tolerance_ppm = 0.0;
    std::optional<double> offset_ppm;  // clock.offset_ppm; unset: drawn within the tolerance from scenario.seed
    double jitter_rms_ps = 0.0;
};

// `nominal_hz`: the clock's nominal frequency, which bounds the jitter (ClockGrid keeps every edge in its order).
void read_oscillator_settings(KeyReader& r, const OscillatorPart& part, std::int64_t nominal_hz, OscillatorSettings& s);

// This unit: the offset set, or drawn uniformly within +-tolerance from the scenario's seed (a draw of its own
// for each part); the jitter's own seed from it too. All zero with clock.ideal.
[[nodiscard]] ClockDeviation clock_deviation(const OscillatorSettings& s, std::uint64_t scenario_seed);

// A board's configuration (any with a ClockDeviation `clock`) on this unit's oscillator.
template <class BoardConfig>
[[nodiscard]] BoardConfig on_oscillator(BoardConfig cfg, const OscillatorSettings& s, std::uint64_t scenario_seed) {
    cfg.clock = clock_deviation(s, scenario_seed);
    return cfg;
}

// The report's "clock" object and its summary line, for the clock the run had.
[[nodiscard]] nlohmann::json oscillator_json(const OscillatorSettings& s, const ClockGrid& clock);
[[nodiscard]] std::string oscillator_text(const OscillatorSettings& s, const ClockGrid& clock);

}  // namespace cnc::sim
