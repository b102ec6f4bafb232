// The atmega system's pins read back from the recorder as the run goes: the motion windows found as PORTB
// changes (motion_windows.hpp), and the STEP pulses the DRV8825s act on (nENBL low: metrics/pulse/enabled_steps.hpp),
// held with the DIR and laser edges until the metrics take them. What is read is dropped from the recorder, so a
// streamed run keeps one slice of edges; read once at the end, the logs are the whole run's.
#pragma once
#include <limits>
#include <map>
#include <string>

#include "architectures/atmega/motion_windows.hpp"
#include "host/core/cad2g/plan.hpp"
#include "metrics/pulse/enabled_steps.hpp"
#include "probes/edge_recorder.hpp"

namespace cnc::sim {

class AtmegaPins {
public:
    // The recorder watches step_x, dir_x, step_y, dir_y, n_enbl_x, n_enbl_y and laser. `keep_raw`: the raw nENBL
    // and STEP logs are kept whole too (the timers toggle STEP while EN is high: only the tests read them).
    AtmegaPins(EdgeRecorder& rec, const host::cad2g::Plan& plan, bool keep_raw);

    // Reads every pin's edges before t_ps (after those of the previous call).
    void read_before(TimePs t_ps);
    // The run stopped at t_sim_end_ps, everything read: the motion under way ends there.
    void finish(TimePs t_sim_end_ps) { m_windows.finish(t_sim_end_ps); }
    [[nodiscard]] const RecordLog<MotionWindow>& windows() const { return m_windows.windows(); }
    void drop_windows_before(std::size_t end) { m_windows.drop_windows_before(end); }

    // The edges read and not handed over yet of a pin the metrics read, those before `before_ps`: step_x and
    // step_y (the pulses the drivers act on), dir_x, dir_y, laser.
    [[nodiscard]] EdgeLog hand_over(const std::string& pin, TimePs before_ps = std::numeric_limits<TimePs>::max());
    // With keep_raw: a raw pin's whole log (n_enbl_x, n_enbl_y, step_x, step_y).
    [[nodiscard]] EdgeLog take_raw(const std::string& pin);

private:
    EdgeRecorder& m_rec;
    bool m_keep_raw;
    metrics::EnabledStepsFold m_driven_x, m_driven_y;
    MotionWindowFold m_windows;
    std::map<std::string, EdgeLog> m_unread;  // by pin, for the metrics
    std::map<std::string, EdgeLog> m_raw;     // by pin, with keep_raw
};

}  // namespace cnc::sim
