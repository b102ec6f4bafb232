// pulse_gen for one axis (seed 004 §5.1.3 pulsegen: a pulse of `duration` clocks every period; here the period is
// the rate word, so STEP rises exactly `period` clocks apart), plus DIR with setup and hold enforced by delaying:
//   - DIR never changes within dir_hold clocks after a STEP rise;
//   - STEP never rises within dir_setup clocks after a DIR change.
// The state is a handful of scheduled pin changes, not a ticking counter. Semantics of a word loaded at edge a
// (it governs from edge a on, so a rise scheduled at a is decided by it):
//   period 0        : stopped, no further rise (a pulse in progress completes; DIR keeps its level);
//   period P > 0    : P' = max(P, pulse + 1) (stretched: STEP keeps at least one low clock); if the direction
//                     differs from DIR, DIR changes at d = max(a, last rise + hold); next rise at
//                     max(a, last DIR change + setup, last rise + spacing), spacing = P' when rates apply
//                     Immediately (the counter compares against the new period at once) and pulse + 1 with
//                     AtNextPulse (the word is only loaded at the edge the running period ends, or when stopped).
// After a rise at R: STEP falls at R + pulse, next rise at R + P'. Edge ties pop as STEP fall, DIR, STEP rise.
#pragma once
#include <cstdint>
#include <optional>

#include "fpga/spi/core/spi_fpga_config.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::fpga {

enum class GenPin { Step, Dir };

struct GenChange {
    std::int64_t edge = 0;
    GenPin pin = GenPin::Step;
    bool level = false;
};

class PulseGenCore {
public:
    explicit PulseGenCore(const SpiFpgaConfig& cfg);

    // Whether the generator takes a FIFO entry at `edge` (AtNextPulse: only when stopped or at its next rise).
    [[nodiscard]] bool reads_at(std::int64_t edge) const;
    // Every change at an edge < `edge` must have been popped; returns true if the word was stretched.
    bool load(std::int64_t edge, const spi::AxisRate& word);
    [[nodiscard]] std::optional<GenChange> next_change() const;
    void pop();  // applies next_change()

    [[nodiscard]] std::uint32_t period_cycles() const { return m_period; }  // 0 = stopped
    [[nodiscard]] bool dir_level() const { return m_dir; }                  // as applied so far
    [[nodiscard]] std::optional<std::int64_t> next_rise() const { return m_next_rise; }

private:
    const SpiFpgaConfig m_cfg;
    std::uint32_t m_period = 0;
    bool m_dir = false;  // reset level: low
    std::optional<std::int64_t> m_last_rise;
    std::optional<std::int64_t> m_last_dir_change;  // applied (popped)
    std::optional<std::int64_t> m_dir_pending;      // scheduled flip of m_dir
    std::optional<std::int64_t> m_fall;
    std::optional<std::int64_t> m_next_rise;
};

}  // namespace cnc::fpga
