// USB 2.0 full-speed frame timing: the host sends a start-of-frame every 1 ms (USB 2.0 §8.4.3.1); bulk data to
// and from a full-speed device such as the CP2102 moves within those frames.
#pragma once
#include "common/units.hpp"

namespace cnc::uart {

inline constexpr TimePs kUsbFullSpeedFramePs = kPsPerMs;  // USB 2.0 §5.12.1: 1 ms frames

// First frame start >= t; frames start at phase_ps + n * frame_ps for every integer n. BadInput if frame_ps <= 0.
[[nodiscard]] TimePs next_frame_start(TimePs t_ps, TimePs frame_ps = kUsbFullSpeedFramePs, TimePs phase_ps = 0);

}  // namespace cnc::uart
