// When each straight move of a streamed job ran, read back from the STEP and DIR pins: grbl reports no execution
// (its "ok" comes when a line is planned, long before it runs), but it runs its blocks in order, each to its end
// point on the step grid. So a move starts at its first STEP pulse after the previous move's end, and ends at the
// pulse that brings both axes' step counts to its end point. The windows are found as the pins are read
// (StepWindowFold, slice by slice during a run).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "common/edge_log.hpp"
#include "common/record_log.hpp"

namespace cnc::sim {

struct StepWindow {
    TimePs t_begin_ps = 0;  // its first STEP pulse (rising edge)
    TimePs t_end_ps = 0;    // its last (the run's end when it stopped first)
    bool complete = true;
};

class StepWindowFold {
public:
    // `ends`: each move's end point in steps from the count at t = 0, in order; no two in a row equal (a move makes at
    // least one step). `dir_high_is_positive`: the DIR level that counts up.
    StepWindowFold(std::vector<std::array<std::int64_t, 2>> ends, bool dir_high_is_positive);

    // The STEP pulses the drivers took and the DIR edges of both axes before an instant, after those of the previous
    // call (each DIR log's initial level the one its pin had before them).
    void add(const EdgeLog& step_x, const EdgeLog& dir_x, const EdgeLog& step_y, const EdgeLog& dir_y);
    // The run stopped at t_sim_end_ps: the move under way, if any, ends there (incomplete).
    void finish(TimePs t_sim_end_ps);

    // The windows of the moves that ended (after finish(): every one that started), numbered over the whole run.
    [[nodiscard]] const RecordLog<StepWindow>& windows() const { return m_windows; }
    void drop_windows_before(std::size_t end) { m_windows.drop_before(end); }
    // The step counts now, and the pulses beyond the last move's end (none on a job that ran as sent).
    [[nodiscard]] const std::array<std::int64_t, 2>& position() const { return m_position; }
    [[nodiscard]] std::int64_t steps_after_last() const { return m_steps_after_last; }

private:
    std::vector<std::array<std::int64_t, 2>> m_ends;
    bool m_dir_high_is_positive;
    std::array<std::int64_t, 2> m_position{};
    std::size_t m_next = 0;  // the move under way or next
    bool m_open = false;     // it has made a step
    TimePs m_begin_ps = 0;   // its first
    std::int64_t m_steps_after_last = 0;
    RecordLog<StepWindow> m_windows;
};

}  // namespace cnc::sim
