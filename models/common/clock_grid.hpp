// The edges of a board's clock as the logic it drives sees them: the oscillator's nominal frequency, this unit's
// frequency offset from it (every oscillator part is specified to a tolerance, in ppm) and its phase jitter (each
// edge early or late by a zero-mean Gaussian amount, white: independent from edge to edge). Every block clocked by
// it (an FPGA's counters, an AVR's timers and USART) times its edges from here, so a fast oscillator makes every
// STEP period short by the same ratio and jitter moves every edge, as a scope sees them on real hardware.
#pragma once
#include <cstdint>

#include "common/units.hpp"

namespace cnc {

// How one unit's oscillator departs from its nominal frequency. All zero: the ideal clock.
struct ClockDeviation {
    double offset_ppm = 0.0;     // (this unit's frequency - nominal) / nominal x 1e6
    double jitter_rms_ps = 0.0;  // rms phase jitter of an edge (its time interval error against the ideal grid)
    std::uint64_t seed = 0;      // draws the jitter: the same seed gives the same edges
};

// The Gaussian draw is cut at this many standard deviations, so no edge passes its neighbour.
inline constexpr double kJitterCutSigmas = 4.0;

// Each block owns its copy; one copy is not for two threads at once (it keeps its last draw).
class ClockGrid {
public:
    // Throws BadInput (naming `where`) for a frequency that is not positive, an offset beyond +-1e5 ppm (10 %, past
    // any oscillator part) or a jitter whose cut Gaussian could reach a quarter of the period.
    ClockGrid(std::int64_t nominal_hz, const ClockDeviation& deviation, const char* where = "clock");

    // This unit's frequency: nominal x (1 + offset), to the nearest hertz (0.06 ppm at 16 MHz).
    [[nodiscard]] std::int64_t hz() const { return m_hz; }
    [[nodiscard]] std::int64_t nominal_hz() const { return m_nominal_hz; }
    // The offset that hz() gives, in ppm.
    [[nodiscard]] double offset_ppm() const;
    [[nodiscard]] double jitter_rms_ps() const { return m_jitter_rms_ps; }
    // The frequency of the coarsest uniform grid every edge falls on: hz() when its period is a whole number of ps and
    // there is no jitter, else 1e12 (each edge on a picosecond of its own: what a VCD must resolve).
    [[nodiscard]] std::int64_t grid_hz() const;

    // Time of edge n (n >= 0; edge 0 at time 0 plus its jitter, never before 0).
    [[nodiscard]] TimePs at(std::int64_t n) const;
    // The last edge at or before t (-1 when t is before edge 0).
    [[nodiscard]] std::int64_t last_at_or_before(TimePs t) const;
    // The first edge strictly after t: the edge that samples a level that changed at t.
    [[nodiscard]] std::int64_t first_after(TimePs t) const { return last_at_or_before(t) + 1; }
    // The first edge at or after t.
    [[nodiscard]] std::int64_t first_at_or_after(TimePs t) const { return last_at_or_before(t - 1) + 1; }

    // Edge n's jitter alone, in ps.
    [[nodiscard]] TimePs jitter_ps(std::int64_t n) const;

private:
    std::int64_t m_nominal_hz;
    std::int64_t m_hz;
    double m_jitter_rms_ps;
    std::uint64_t m_seed;
    // The last edge drawn and its jitter: a block asks for the edge at a time, then for that edge's time.
    mutable std::int64_t m_drawn_edge = 0;
    mutable TimePs m_drawn_jitter_ps = 0;
};

}  // namespace cnc
