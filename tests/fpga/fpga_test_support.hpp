// Shared helpers of the SystemC FPGA tests: senders, edge-log comparison, scenario clocks.
#pragma once
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "fpga_bench.hpp"
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

// Every pin: same initial level and the same edges (time and level).
inline void expect_same_edges(const std::map<std::string, EdgeLog>& reference,
                              const std::map<std::string, EdgeLog>& model) {
    for (const std::string& pin : fpga_pins()) {
        const EdgeLog& r = reference.at(pin);
        const EdgeLog& m = model.at(pin);
        EXPECT_EQ(r.initial, m.initial) << pin;
        const std::size_t n = std::min(r.edges.size(), m.edges.size());
        for (std::size_t i = 0; i < n; ++i) {
            if (r.edges[i].t_ps != m.edges[i].t_ps || r.edges[i].level != m.edges[i].level) {
                ADD_FAILURE() << pin << " edge #" << i << ": reference " << r.edges[i].level << " at cycle "
                              << r.edges[i].t_ps / kCyclePs << ", model " << m.edges[i].level << " at cycle "
                              << m.edges[i].t_ps / kCyclePs;
                break;
            }
        }
        EXPECT_EQ(r.edges.size(), m.edges.size()) << pin;
    }
}

}  // namespace cnc::fpga::test
