// The atmega system's pins read back from the recorder as the run goes (avr_board/driven_pins.hpp), and the motion
// windows found as PORTB changes (motion_windows.hpp).
#pragma once
#include <limits>
#include <string>

#include "architectures/atmega/motion_windows.hpp"
#include "architectures/avr_board/driven_pins.hpp"
#include "host/core/cad2g/plan.hpp"

namespace cnc::sim {

class AtmegaPins {
public:
    // As DrivenPins.
    AtmegaPins(EdgeRecorder& rec, const host::cad2g::Plan& plan, bool keep_raw);

    // Reads every pin's edges before t_ps (after those of the previous call).
    void read_before(TimePs t_ps);
    // The run stopped at t_sim_end_ps, everything read: the motion under way ends there.
    void finish(TimePs t_sim_end_ps) { m_windows.finish(t_sim_end_ps); }
    [[nodiscard]] const RecordLog<MotionWindow>& windows() const { return m_windows.windows(); }
    void drop_windows_before(std::size_t end) { m_windows.drop_windows_before(end); }

    [[nodiscard]] EdgeLog hand_over(const std::string& pin, TimePs before_ps = std::numeric_limits<TimePs>::max()) {
        return m_pins.hand_over(pin, before_ps);
    }
    [[nodiscard]] DrivenPins& driven() { return m_pins; }

private:
    DrivenPins m_pins;
    MotionWindowFold m_windows;
};

}  // namespace cnc::sim
