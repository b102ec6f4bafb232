// Test bench for the ATmega328P model: an AvrCore with every output bound to a signal whose edges are logged,
// an optional RXD driver, and exact cycle/ps helpers. One elaboration per test process (ctest runs each TEST
// separately).
#pragma once
#define SC_INCLUDE_DYNAMIC_PROCESSES
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <systemc>
#include <vector>

#include "avr/avr_core.hpp"
#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::avr::test {

inline constexpr TimePs kCyclePs = 62'500;  // 16 MHz (seed 003 §5.2.4)
inline constexpr TimePs ps_of(Cycle c) {
    return c * kCyclePs;
}
inline TimePs now_ps() {
    return static_cast<TimePs>(sc_core::sc_time_stamp().value());
}
inline sc_core::sc_time at_ps(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

inline AvrCoreConfig config_for(const std::string& elf) {
    AvrCoreConfig cfg;
    cfg.firmware_elf = elf;
    return cfg;
}

// For the tests that read UsartUnit::tx_log() / rx_log().
inline AvrCoreConfig config_with_usart_logs(const std::string& elf) {
    AvrCoreConfig cfg = config_for(elf);
    cfg.keep_usart_logs = true;
    return cfg;
}

class AvrBench {
public:
    explicit AvrBench(const AvrCoreConfig& cfg) : avr("avr", cfg) {
        for (std::size_t i = 0; i < kLineCount; ++i) {
            signals[i] = std::make_unique<sc_core::sc_signal<bool>>(("line" + std::to_string(i)).c_str(),
                                                                    avr.chip().initial_level(static_cast<int>(i)));
            logs[i].name = i < kPinSignals.size() ? std::string(kPinSignals[i]) : "txd";
            logs[i].initial = avr.chip().initial_level(static_cast<int>(i));
        }
        avr.step_x(*signals[0]);
        avr.dir_x(*signals[1]);
        avr.en_x(*signals[2]);
        avr.step_y(*signals[3]);
        avr.dir_y(*signals[4]);
        avr.en_y(*signals[5]);
        avr.head(*signals[6]);
        avr.txd(*signals[kTxdLine]);
        avr.rxd(rxd);
        for (std::size_t i = 0; i < kLineCount; ++i) {
            sc_core::sc_spawn_options opt;
            opt.spawn_method();
            opt.dont_initialize();
            opt.set_sensitivity(&signals[i]->value_changed_event());
            sc_core::sc_spawn([this, i] { logs[i].add(now_ps(), signals[i]->read()); }, nullptr, &opt);
        }
    }

    // Runs until `t_ps` of simulated time.
    void run_until_ps(TimePs t_ps) { sc_core::sc_start(at_ps(t_ps - now_ps())); }

    [[nodiscard]] const EdgeLog& log(std::string_view signal) const {
        for (const auto& l : logs)
            if (l.name == signal) return l;
        throw std::runtime_error("no line " + std::string(signal));
    }
    [[nodiscard]] std::vector<TimePs> edges(std::string_view signal) const {
        std::vector<TimePs> out;
        for (const Edge& e : log(signal).edges) out.push_back(e.t_ps);
        return out;
    }

    sc_core::sc_signal<bool> rxd{"rxd", true};
    AvrCore avr;
    std::array<std::unique_ptr<sc_core::sc_signal<bool>>, kLineCount> signals;
    std::array<EdgeLog, kLineCount> logs;
};

// The cycle of an edge time (asserting it lies on a cycle boundary).
inline Cycle cycle_of(TimePs t) {
    EXPECT_EQ(t % kCyclePs, 0) << "edge at " << t << " ps is not on a 62.5 ns cycle boundary";
    return t / kCyclePs;
}

// Cycle of the first rising edge of a marker line (-1 and a test failure when it never rose).
inline Cycle first_rise(const AvrBench& b, std::string_view line) {
    const auto r = b.log(line).rising();
    EXPECT_FALSE(r.empty()) << line;
    return r.empty() ? -1 : cycle_of(r.front());
}

// Cycles of every edge of a line.
inline std::vector<Cycle> edge_cycles(const AvrBench& b, std::string_view line) {
    std::vector<Cycle> out;
    for (const TimePs t : b.edges(line)) out.push_back(cycle_of(t));
    return out;
}

}  // namespace cnc::avr::test
