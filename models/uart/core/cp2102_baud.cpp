#include "uart/core/cp2102_baud.hpp"

#include <array>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::uart {

namespace {

struct RateRange {
    std::uint32_t low;
    std::uint32_t high;
    std::uint32_t rate;
};

// AN205 Rev 0.3 Table 1 "Default Baud Rate Configuration" (requested low..high -> UART rate). Requests above
// 1 053 257 Bd are "Undefined" in the table: not supported here.
constexpr std::array<RateRange, 29> kAn205Table1{{
    {670'255, 1'053'257, 921'600},
    {567'139, 670'254, 576'000},
    {491'521, 567'138, 500'000},
    {273'067, 491'520, 460'800},
    {254'235, 273'066, 256'000},
    {237'833, 254'234, 250'000},
    {156'869, 237'832, 230'400},
    {129'348, 156'868, 153'600},
    {117'029, 129'347, 128'000},
    {77'609, 117'028, 115'200},
    {64'112, 77'608, 76'800},
    {58'054, 64'111, 64'000},
    {56'281, 58'053, 57'600},
    {51'559, 56'280, 56'000},
    {38'602, 51'558, 51'200},
    {28'913, 38'601, 38'400},
    {19'251, 28'912, 28'800},
    {16'063, 19'250, 19'200},
    {14'429, 16'062, 16'000},
    {9'613, 14'428, 14'400},
    {7'208, 9'612, 9'600},
    {4'804, 7'207, 7'200},
    {4'001, 4'803, 4'800},
    {2'401, 4'000, 4'000},
    {1'801, 2'400, 2'400},
    {1'201, 1'800, 1'800},
    {601, 1'200, 1'200},
    {301, 600, 600},
    {57, 300, 300},
}};

}  // namespace

std::uint32_t cp2102_table_rate(std::uint32_t requested) {
    for (const RateRange& r : kAn205Table1) {
        if (requested >= r.low && requested <= r.high) return r.rate;
    }
    throw BadInput("", "baud rate " + std::to_string(requested) +
                           " is not supported by the CP2102 (AN205 Table 1: 57..1053257 Bd)");
}

Cp2102Baud cp2102_baud(std::uint32_t requested, bool ideal) {
    Cp2102Baud b;
    b.requested = requested;
    if (ideal) {
        if (requested == 0) throw BadInput("", "baud rate must be > 0");
        b.table_rate = requested;
        b.divider = 1;
        b.clk_hz = requested;
    } else {
        b.table_rate = cp2102_table_rate(requested);
        b.divider = (kCp2102ClockHz + b.table_rate / 2) / b.table_rate;  // round to nearest
        b.clk_hz = kCp2102ClockHz;
    }
    b.actual_bd = static_cast<double>(b.clk_hz) / static_cast<double>(b.divider);
    b.error_pct = (b.actual_bd / static_cast<double>(requested) - 1.0) * 100.0;
    return b;
}

}  // namespace cnc::uart
