#include "uart/core/usb_timing.hpp"

#include "common/bad_input.hpp"

namespace cnc::uart {

TimePs next_frame_start(TimePs t_ps, TimePs frame_ps, TimePs phase_ps) {
    if (frame_ps <= 0) throw BadInput("", "USB frame period must be > 0");
    const TimePs rel = t_ps - phase_ps;
    // Ceiling division that is also right for negative rel.
    TimePs n = rel / frame_ps;
    if (n * frame_ps < rel) ++n;
    return phase_ps + n * frame_ps;
}

}  // namespace cnc::uart
