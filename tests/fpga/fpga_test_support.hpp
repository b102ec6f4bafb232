// Shared helpers of the SystemC FPGA tests: senders, edge-log comparison, scenario clocks.
#pragma once
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "fpga_bench.hpp"
#include "support/edge_log_diff.hpp"
#include "uart_wave.hpp"

namespace cnc::fpga::test {

constexpr TimePs kUs = kPsPerUs;
constexpr TimePs kMs = kPsPerMs;
constexpr TimePs kCyclePs = 20'000;  // 50 MHz

// A sender clocked like the FPGA (434 cycles per bit) and the CP2102 (24 MHz / 208 = 115,384.6 Bd).
inline UartWave sync_sender() {
    return UartWave(50'000'000, 434);
}
inline UartWave cp2102_sender() {
    return UartWave(24'000'000, 208);
}

inline std::int64_t edge_of(TimePs t_ps) {
    return t_ps / kCyclePs;
}

// Every pin of `pins`: same initial level and the same edges (time and level).
inline void expect_same_edges(const std::map<std::string, EdgeLog>& reference,
                              const std::map<std::string, EdgeLog>& model,
                              const std::vector<std::string>& pins = fpga_pins()) {
    for (const std::string& pin : pins) {
        EXPECT_EQ(cnc::test::first_difference(reference.at(pin), model.at(pin)), "") << pin << ": reference vs model";
    }
}

// Init, every kind of motion packet, a packet and an init while busy, a dropped ACK, glitches, a framing
// error and a truncated packet (each cleared by the 100 ms watchdog).
inline std::int64_t mixed_stream(UartWave& w) {
    w.bytes(10 * kUs, init_packet(300'000, 200'000));
    w.bytes(2 * kMs, motion_packet(1, 20, -10, 1000));        // X dominant: 300 / 600 cycles
    w.bytes(4 * kMs, motion_packet(0, -7, 12, 2000));         // Y dominant at 100 cycles: STEP_Y one long pulse
    w.bytes(6 * kMs, motion_packet(1, 0, 0, 500));            // zero length, still ACKed
    w.bytes(8 * kMs, motion_packet(2, 15, 0, 1500));          // X only
    w.bytes(10 * kMs, motion_packet(3, 0, -9, 1000));         // Y only, negative
    w.bytes(12 * kMs, motion_packet(1, 4, 3, 2970));          // period 101: one low cycle between pulses
    w.bytes(14 * kMs, motion_packet(1, 2, -1, 0));            // feed 0: both 62,500
    TimePs t = w.bytes(18 * kMs, motion_packet(1, 3, 0, 0));  // 3.75 ms move ...
    t = w.bytes(t, motion_packet(0, 1, 1, 1000));             // ... this one is lost, and turns the laser off
    w.bytes(t, init_packet(150'000, 150'000));                // ... and this init is not applied
    w.bytes(24 * kMs, motion_packet(1, 5, 5, 1000));          // still the first numerators
    t = w.bytes(26 * kMs, motion_packet(1, 230, 0, 1500));    // N = 46,000: ends just before the next arrives
    w.bytes(t, motion_packet(1, 0, 0, 100));                  // accepted; its busy falls during the ACK: dropped
    w.glitch(30 * kMs + 5 * kPsPerNs, 5 * kPsPerNs);          // between two edges: invisible
    w.glitch(30'100 * kUs - 2 * kPsPerNs, 5 * kPsPerNs);      // across an edge: S_START, then back to S_IDLE
    w.glitch(30'200 * kUs, 1 * kUs);                          // shorter than HALF_BIT
    w.bytes(31 * kMs, motion_packet(1, -3, -4, 1000));
    const std::vector<std::uint8_t> p = motion_packet(1, 7, 7, 1000);
    t = w.bytes(33 * kMs, {p.begin(), p.begin() + 5});
    t = w.byte(t, p[5], false) + 10 * kUs;  // bad stop bit: byte dropped, packet incomplete
    w.bytes(t, {p.begin() + 6, p.end()});
    w.bytes(140 * kMs, motion_packet(1, 6, -6, 1000));  // after the watchdog
    w.bytes(142 * kMs, {p.begin(), p.begin() + 5});     // truncated packet
    w.bytes(250 * kMs, motion_packet(1, 1, 2, 1000));
    return edge_of(253 * kMs);
}

}  // namespace cnc::fpga::test
