// How far apart the bit rates of the two ends of an asynchronous line may be.
//
// A receiver times a whole frame from the falling edge of its start bit and samples each bit in its middle by its
// own bit clock, so it samples the first stop bit (1 + data + parity) + 0.5 of ITS bit times after the edge: 9.5
// for 8N1. That sample must fall inside the sender's stop bit, 9 to 10 of the SENDER's bit times after the edge:
//     9 <= 9.5 x f_sender / f_receiver < 10,   i.e.   |f_sender / f_receiver - 1| < 0.5 / 9.5 = 5.26 %,
// the same bound whichever end is faster (each direction of the line checks its own ratio). That is the whole
// budget of both ends together with ideal edges and an ideal mid-bit sample. Real receivers spend part of it on
// finding the start edge and voting (the ATmega328P's 16x oversampling: datasheet §20.8.3 "Asynchronous
// Operational Range"), real lines on slow edges, so this project allows half of it, 0.5 / 9.5 / 2 = 2.63 %: the
// common rule of halving the budget for margin. The seed 003 link (CP2102 57 553.96 Bd against the AVR's
// 58 823.5 Bd, +2.21 %) ran on the thesis's bench and is within it; seed 000's (CP2102 115 384.6 Bd against the
// FPGA's 50 MHz / 434 = 115 207.4 Bd, +0.15 %) too.
#pragma once

#include "uart/core/uart_frame.hpp"

namespace cnc::uart {

// Bit times from the start edge to the receiver's sample of the first stop bit: 9.5 for 8N1.
[[nodiscard]] double stop_sample_bits(const FrameFormat& fmt);

// The rate difference allowed between the two ends, as a fraction: 0.5 / stop_sample_bits / 2 (2.63 % for 8N1).
[[nodiscard]] double max_rate_mismatch(const FrameFormat& fmt);

// a / b - 1: how much faster end a runs than end b, as a fraction.
[[nodiscard]] double rate_mismatch(double a_bd, double b_bd);

// True when frames get through in both directions with the margin above: |a/b - 1| and |b/a - 1| within
// max_rate_mismatch().
[[nodiscard]] bool rates_within_tolerance(double a_bd, double b_bd, const FrameFormat& fmt);

}  // namespace cnc::uart
