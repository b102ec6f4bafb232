// The commanded moves handed to the metrics as the controller's execution windows come (a window per stepped move,
// in order, read back from the pins as the run goes): each move with its window once that window has ended; a move
// too short for a microstep (run/moves.hpp, unstepped) placed at the next window's begin.
#pragma once
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "common/record_log.hpp"
#include "metrics/run_input.hpp"
#include "run/moves.hpp"

namespace cnc::sim {

class WindowedMoves {
public:
    explicit WindowedMoves(std::vector<metrics::MoveSpec> commanded) : m_commanded(std::move(commanded)) {}

    // Hands `f` the moves whose windows have ended, in order: `executed(move, window)` makes a stepped move's
    // executed record. An unstepped move waits for the next window's begin, or once the run has ended (`final`)
    // takes the instant after the last window.
    template <typename Window, typename Executed, typename F>
    void hand(const RecordLog<Window>& windows, Executed executed, F f, bool final) {
        for (; m_handed < m_commanded.size(); ++m_handed) {
            metrics::MoveSpec m = m_commanded[m_handed];
            if (is_unstepped(m)) {
                if (m_window == windows.size() && !final) return;
                place_unstepped(m,
                                m_window < windows.size() ? std::optional(windows[m_window].t_begin_ps) : std::nullopt,
                                m_last_end_ps);
                f(std::move(m));
                continue;
            }
            if (m_window == windows.size()) return;
            m_last_end_ps = windows[m_window].t_end_ps;
            f(executed(std::move(m), windows[m_window++]));
        }
    }
    // The windows before this index have been handed over.
    [[nodiscard]] std::size_t next_window() const { return m_window; }
    [[nodiscard]] const std::vector<metrics::MoveSpec>& commanded() const { return m_commanded; }

private:
    const std::vector<metrics::MoveSpec> m_commanded;
    std::size_t m_handed = 0;  // commanded moves handed to the metrics
    std::size_t m_window = 0;  // windows handed to the metrics
    TimePs m_last_end_ps = 0;  // the end of the last window handed
};

}  // namespace cnc::sim
