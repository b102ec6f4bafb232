// An ideal asynchronous receiver: decodes one frame from a line's transition history.
//
// It samples the middle of every bit, timed from the falling edge that starts the frame: bit k at
// t_fall + (k + 0.5) bit times of the RECEIVER's clock. Real receivers (the CP2102, AVR USART, most FPGA
// UARTs) oversample x16 and majority-vote three samples around the middle; on a clean line that is the same
// decision, so mid-bit sampling is the usual model. A transmitter whose rate differs from the receiver's
// drifts by the mismatch each bit; the stop bit, sampled at 9.5 bits in 8N1, is the first to fail, near a
// 5 % mismatch (0.5 bit / 9.5 bits).
#pragma once
#include <cstdint>

#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "uart/core/uart_frame.hpp"

namespace cnc::uart {

enum class RxStatus {
    Ok,
    FalseStart,  // the line was high again at the middle of the start bit: a glitch, no frame
    ParityError,
    FramingError,  // a stop bit sampled low
};

struct RxFrame {
    std::uint8_t byte = 0;
    RxStatus status = RxStatus::Ok;
    TimePs t_decision_ps = 0;  // middle of the last stop bit: when the receiver knows the outcome
    TimePs t_stop_end_ps = 0;  // end of the frame by the receiver's clock
};

// `line` must hold the transitions up to at least the decision time; `t_fall_ps` is the start edge.
[[nodiscard]] RxFrame receive_frame(const EdgeLog& line, TimePs t_fall_ps, BitClock clk,
                                    const FrameFormat& fmt = kFormat8N1);

// Offset from the start edge to the receiver's decision (middle of the last stop bit).
[[nodiscard]] TimePs decision_offset_ps(BitClock clk, const FrameFormat& fmt = kFormat8N1);

}  // namespace cnc::uart
