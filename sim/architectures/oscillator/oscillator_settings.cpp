#include "architectures/oscillator/oscillator_settings.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/splitmix64.hpp"

namespace cnc::sim {

namespace {

constexpr std::uint64_t kOffsetStream = 0x636c6f636b6f6666ULL;  // "clockoff"
constexpr std::uint64_t kJitterStream = 0x636c6f636b6a6974ULL;  // "clockjit"

// FNV-1a, 64 bit: a stable number for a part's key table.
std::uint64_t name_hash(const std::string& name) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    return h;
}

}  // namespace

void read_oscillator_settings(KeyReader& r, const OscillatorPart& part, std::int64_t nominal_hz,
                              OscillatorSettings& s) {
    const std::string t = part.table;
    s.part = part.name;
    s.table = part.table;
    s.ideal = r.get_bool("clock.ideal", false,
                         "every clock ideal: no offset and no jitter (the step arithmetic of the designs alone)");
    s.offset_ppm = r.get_optional_float(
        "clock.offset_ppm", -1e5, 1e5, "drawn from scenario.seed within the tolerance",
        "this unit's frequency offset from nominal, ppm; unset: drawn uniformly within the part's tolerance");
    s.tolerance_ppm = r.get_float(t + ".clock_tolerance_ppm", part.tolerance_ppm, 0.0, 1e5,
                                  fmt::format(FMT_STRING("the clock part's frequency tolerance, +- ppm ({}: {})"),
                                              part.name, part.tolerance_from));
    s.jitter_rms_ps =
        r.get_float(t + ".clock_jitter_rms_ps", part.jitter_rms_ps, 0.0, 1e6,
                    fmt::format(FMT_STRING("rms phase jitter of the clock's edges, ps ({})"), part.jitter_from));
    // The fastest unit's period, over ClockGrid's bound of 4 sigma < a quarter period.
    const double max_jitter_ps =
        1e12 / (static_cast<double>(nominal_hz) * (1.0 + s.tolerance_ppm * 1e-6)) / (16.0 + 1e-9);
    if (s.jitter_rms_ps >= max_jitter_ps) {
        r.fail(t + ".clock_jitter_rms_ps",
               fmt::format(FMT_STRING("{:g} ps: must be below a sixteenth of the clock's period ({:.1f} ps), so that "
                                      "no edge passes its neighbour"),
                           s.jitter_rms_ps, max_jitter_ps));
    }
    if (s.offset_ppm && std::abs(*s.offset_ppm) > s.tolerance_ppm) {
        r.fail("clock.offset_ppm", fmt::format(FMT_STRING("{:g} ppm is outside the part's tolerance of +-{:g} ppm "
                                                          "({}); raise {}.clock_tolerance_ppm for a part out of "
                                                          "specification"),
                                               *s.offset_ppm, s.tolerance_ppm, part.name, t));
    }
}

ClockDeviation clock_deviation(const OscillatorSettings& s, std::uint64_t scenario_seed) {
    if (s.ideal) return {};
    const std::uint64_t part_seed = splitmix64(scenario_seed ^ name_hash(s.table));
    ClockDeviation d;
    if (s.offset_ppm) {
        d.offset_ppm = *s.offset_ppm;
    } else {
        const double unit = static_cast<double>(splitmix64(part_seed ^ kOffsetStream) >> 11U) / 9007199254740992.0;
        d.offset_ppm = (2.0 * unit - 1.0) * s.tolerance_ppm;
    }
    d.jitter_rms_ps = s.jitter_rms_ps;
    d.seed = splitmix64(part_seed ^ kJitterStream);
    return d;
}

nlohmann::json oscillator_json(const OscillatorSettings& s, const ClockGrid& clock) {
    return {{"part", s.part},
            {"exact", s.ideal},  // clock.ideal
            {"nominal_hz", clock.nominal_hz()},
            {"hz", clock.hz()},
            {"tolerance_ppm", s.tolerance_ppm},
            {"offset_ppm", clock.offset_ppm()},
            {"offset_drawn", !s.ideal && !s.offset_ppm},
            {"jitter_rms_ps", clock.jitter_rms_ps()}};
}

std::string oscillator_text(const OscillatorSettings& s, const ClockGrid& clock) {
    if (s.ideal) {
        return fmt::format(FMT_STRING("clock: {} taken as ideal (clock.ideal): {} Hz, no offset, no jitter\n"), s.part,
                           clock.nominal_hz());
    }
    return fmt::format(FMT_STRING("clock: {}, +-{:g} ppm: this unit {:+.3f} ppm ({}), {} Hz; jitter {:g} ps rms\n"),
                       s.part, s.tolerance_ppm, clock.offset_ppm(),
                       s.offset_ppm ? "clock.offset_ppm" : "drawn from scenario.seed", clock.hz(),
                       clock.jitter_rms_ps());
}

}  // namespace cnc::sim
