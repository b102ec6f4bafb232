// The chords that started late (seed 003 §5.4.3: the MCU had the next chord's last byte only after the chord
// before had ended, and Y kept stepping meanwhile), found as the run goes: the MCU's receive instant of each
// transfer's last byte and the motion windows are folded in as they come, so that the link's per-byte records can
// be dropped once read.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "architectures/atmega/motion_windows.hpp"
#include "common/record_log.hpp"
#include "common/units.hpp"
#include "host/core/cad2g/plan.hpp"

namespace cnc::sim {

struct ChordGaps {
    int late = 0;                      // chords whose last byte the MCU received after the chord before had ended
    TimePs wait_max_ps = 0;            // longest end-of-chord to reload gap
    std::int64_t y_steps_waiting = 0;  // Y steps the driver took in those gaps
};

class ChordGapFold {
public:
    explicit ChordGapFold(const std::vector<host::cad2g::Transfer>& transfers) : m_transfers(transfers) {}

    // The MCU's receiver had a byte of transfer `transfer` at t_ps (the middle of its stop bit at the MCU's bit
    // clock). Bytes come in the order they were written.
    void add_byte(std::size_t transfer, TimePs t_ps);
    // The windows from next_window() on, in plan order. A chord is judged once a byte of a later transfer has
    // come, or, with `ended` (no byte comes any more), at once: the chords not judged yet wait for the next call.
    void add_windows(const RecordLog<MotionWindow>& windows, bool ended);
    [[nodiscard]] std::size_t next_window() const { return m_next_window; }
    [[nodiscard]] const ChordGaps& gaps() const { return m_gaps; }

private:
    // When the MCU had the last byte of `transfer`, -1 if none came; forgets the transfers before it.
    [[nodiscard]] TimePs arrival(std::size_t transfer);
    [[nodiscard]] std::size_t transfer_of(const MotionWindow& w);

    const std::vector<host::cad2g::Transfer>& m_transfers;
    std::deque<std::pair<std::size_t, TimePs>> m_last_byte;  // per transfer not judged yet: its last byte so far
    std::size_t m_transfer = 0;                              // where transfer_of() looks from
    std::size_t m_next_window = 0;
    std::optional<MotionWindow> m_prev;  // the window before m_next_window
    ChordGaps m_gaps;
};

}  // namespace cnc::sim
