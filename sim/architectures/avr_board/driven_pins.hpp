// The machine's pins as an MCU that drives the DRV8825s' nENBL leaves them, read back from the recorder as the run
// goes: the STEP pulses the drivers act on (nENBL low: metrics/pulse/enabled_steps.hpp), held with the DIR and laser
// edges until the metrics take them. What is read is dropped from the recorder, so a streamed run keeps one slice of
// edges; read once at the end, the logs are the whole run's.
#pragma once
#include <limits>
#include <map>
#include <string>

#include "metrics/pulse/enabled_steps.hpp"
#include "probes/edge_recorder.hpp"

namespace cnc::sim {

// One read's edges of every pin; step_x and step_y are the pulses the drivers took.
struct PinSlice {
    EdgeLog step_x, dir_x, step_y, dir_y, n_enbl_x, n_enbl_y, laser;
};

class DrivenPins {
public:
    // The recorder watches step_x, dir_x, step_y, dir_y, n_enbl_x, n_enbl_y and laser. `keep_raw`: the raw nENBL
    // and STEP logs are kept whole too (an MCU's timers may toggle STEP while EN is high: only the tests read them).
    DrivenPins(EdgeRecorder& rec, bool keep_raw);

    // Reads every pin's edges before t_ps (after those of the previous call) and returns them.
    PinSlice read_before(TimePs t_ps);
    // The edges read and not handed over yet of a pin the metrics read, those before `before_ps`: step_x and
    // step_y (the pulses the drivers act on), dir_x, dir_y, laser.
    [[nodiscard]] EdgeLog hand_over(const std::string& pin, TimePs before_ps = std::numeric_limits<TimePs>::max());
    // With keep_raw: a raw pin's whole log (n_enbl_x, n_enbl_y, step_x, step_y).
    [[nodiscard]] EdgeLog take_raw(const std::string& pin);

private:
    EdgeRecorder& m_rec;
    bool m_keep_raw;
    metrics::EnabledStepsFold m_driven_x, m_driven_y;
    std::map<std::string, EdgeLog> m_unread;  // by pin, for the metrics
    std::map<std::string, EdgeLog> m_raw;     // by pin, with keep_raw
};

}  // namespace cnc::sim
