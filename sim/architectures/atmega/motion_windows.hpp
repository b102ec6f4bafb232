// When each seed 003 motion (a G00, a G01, one arc chord) ran, read back from the PORTB pins: every start byte
// the firmware writes changes at least one of EN_X, EN_Y, DIR_X, DIR_Y, HEADER at one instant (a single OUT),
// and nothing else changes them except the end of a count (App. A2-A4):
//   * a command starts when an EN pin goes low after both were high, and a G00/G01 ends when both are high;
//   * a chord ends when the Timer0 ISR has counted X to zero, which raises EN_X alone, and the next chord starts
//     at the next PORTB change that is not EN_X rising alone (the reload: EN_X falls, or, for a chord with
//     dx = 0, DIR_X flips, which the PC program guarantees for exactly that purpose: plan.hpp);
//   * a chord whose X was disabled (dx = 0) ends where the next one starts; the last chord of an arc ends at its
//     ISR, or where both EN pins are high.
// Y steps between a chord's end and the next reload (late data: seed 003 §5.4.3 "the motion continues") belong
// to the chord that ended.
// The windows are found as the pins change (MotionWindowFold, fed slice by slice during a run); a window is final
// once the PORTB change that closes it is seen. motion_windows() is the fold fed the whole run at once.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "common/edge_log.hpp"
#include "common/record_log.hpp"
#include "host/core/cad2g/plan.hpp"

namespace cnc::sim {

struct PortbLines {
    const EdgeLog& en_x;
    const EdgeLog& en_y;
    const EdgeLog& dir_x;
    const EdgeLog& dir_y;
    const EdgeLog& head;
};

struct MotionWindow {
    std::size_t command = 0;  // index into Plan::commands
    std::size_t motion = 0;   // index into the command's motions
    TimePs t_begin_ps = 0;    // the start byte (or chord reload) was written
    TimePs t_end_ps = 0;      // the count ended (t_sim_end_ps when the run stopped first)
    bool complete = true;     // false: the run stopped before the motion ended
    // The Y STEP pulses the driver took before t_begin_ps, and up to t_end_ps included: what Y did between a
    // chord's end and the next reload, without keeping its edges.
    std::int64_t y_steps_before_begin = 0;
    std::int64_t y_steps_through_end = 0;
};

class MotionWindowFold {
public:
    explicit MotionWindowFold(const host::cad2g::Plan& plan);

    // The PORTB pins' edges before an instant, after those of the previous call (each log's initial level the one
    // its pin had before them: EdgeRecorder::take_before), and the Y STEP pulses the driver took before the same
    // instant (metrics::EnabledStepsFold).
    void add(const PortbLines& lines, const EdgeLog& y_steps);
    // The run stopped at t_sim_end_ps: the motion under way, if any, ends there (incomplete).
    void finish(TimePs t_sim_end_ps);
    // The windows of the motions that started and ended (after finish(): every one that started), in plan order,
    // numbered over the whole run (size() counts the dropped ones too).
    [[nodiscard]] const RecordLog<MotionWindow>& windows() const { return m_windows; }
    // The readers have read the windows before index `end`: they go.
    void drop_windows_before(std::size_t end) { m_windows.drop_before(end); }

private:
    // The PORTB pins at one instant where any of them changed, with the Y steps before and up to it.
    struct PortEvent {
        TimePs t_ps = 0;
        bool en_x_high = false;
        bool en_y_high = false;
        bool en_x_rise_alone = false;  // the end of an ISR count: nothing but EN_X, rising
        std::int64_t y_before = 0;
        std::int64_t y_through = 0;
    };

    void add(const PortEvent& e);
    // The next command with motions from `from` on, if any.
    [[nodiscard]] std::optional<std::size_t> command_from(std::size_t from) const;
    void begin(const PortEvent& e);
    void close(TimePs t_end_ps, std::int64_t y_through, bool complete);
    [[nodiscard]] bool arc() const;
    [[nodiscard]] bool last_motion() const;

    const host::cad2g::Plan& m_plan;
    std::int64_t m_y_steps = 0;            // Y steps handed over so far
    std::optional<std::size_t> m_command;  // the command whose start is awaited, or under way
    bool m_running = false;                // a motion of m_command is under way
    MotionWindow m_open;                   // that motion
    std::optional<PortEvent> m_isr;        // its ISR end, once seen
    RecordLog<MotionWindow> m_windows;
};

// Windows of the motions that started, in plan order. `t_sim_end_ps` closes a motion the run did not finish.
[[nodiscard]] std::vector<MotionWindow> motion_windows(const host::cad2g::Plan& plan, const PortbLines& lines,
                                                       TimePs t_sim_end_ps);

}  // namespace cnc::sim
