// What a receiver made of the frames a sender put on a line with faults: each frame sent is matched with the frames
// the receiver framed from it (by where their start bits fell), so that a study can count the bytes that arrived
// as sent, arrived wrong, never arrived, and the ones the receiver framed out of nothing (a data bit taken for a
// start bit after an inverted start bit, or a frame cut in two).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/units.hpp"

namespace cnc::uart {

struct SentFrame {
    TimePs t_start_ps = 0;  // the start bit's falling edge on the sender's pin
    TimePs t_end_ps = 0;    // the end of its (last) stop bit
    std::uint8_t byte = 0;
};

struct ReceivedFrame {
    TimePs t_start_ps = 0;  // the falling edge the receiver took for a start bit
    std::uint8_t byte = 0;
    bool framing_error = false;  // stop bit sampled low: the byte is handed over all the same, with the flag
};

enum class FrameFate {
    AsSent,  // framed from its own start bit, with its data bits
    Wrong,   // the first frame the receiver framed within it is misframed or has a wrong data bit
    Lost,    // the receiver framed nothing within it
};

struct FrameMatch {
    std::vector<FrameFate> fate;     // per frame sent
    std::vector<std::size_t> extra;  // per frame sent: the further frames framed within it
    std::size_t as_sent = 0;
    std::size_t wrong = 0;
    std::size_t lost = 0;
    std::size_t extra_frames = 0;     // framed within a frame sent after its first (or before every frame sent)
    std::size_t framing_flagged = 0;  // received frames with the framing-error flag
};

// `sent` and `received` in time order. A received frame belongs to the frame sent whose span
// [t_start - start_tolerance, t_end) holds its start; it is that frame's own when its start is within
// start_tolerance_ps of the sent start bit (the receiver's clock grid). The receiver must have seen every frame sent
// (received frames past the last one's end are extra).
[[nodiscard]] FrameMatch match_frames(const std::vector<SentFrame>& sent, const std::vector<ReceivedFrame>& received,
                                      TimePs start_tolerance_ps);

}  // namespace cnc::uart
