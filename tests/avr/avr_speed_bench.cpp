// Speed of the ATmega328P model inside SystemC (not a test: wall-clock numbers). Runs a firmware for a simulated
// time and prints simulated MHz and the real-time factor. Usage: avr_speed_bench <firmware.elf> [ms] [quantum]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <systemc>

#include "avr/avr_core.hpp"

int sc_main(int argc, char* argv[]) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s <firmware.elf> [simulated ms, default 1000] [quantum cycles]\n", argv[0]);
        return 2;
    }
    cnc::avr::AvrCoreConfig cfg;
    cfg.firmware_elf = argv[1];
    const long ms = argc > 2 ? std::atol(argv[2]) : 1000;
    if (argc > 3) cfg.quantum_cycles = static_cast<std::uint32_t>(std::atol(argv[3]));
    cnc::avr::AvrCore avr("avr", cfg);
    std::array<sc_core::sc_signal<bool>, cnc::avr::kLineCount> lines;
    sc_core::sc_signal<bool> rxd("rxd", true);
    avr.step_x(lines[0]);
    avr.dir_x(lines[1]);
    avr.en_x(lines[2]);
    avr.step_y(lines[3]);
    avr.dir_y(lines[4]);
    avr.en_y(lines[5]);
    avr.head(lines[6]);
    avr.txd(lines[cnc::avr::kTxdLine]);
    avr.rxd(rxd);
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(ms) * 1'000'000'000ULL));
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double sim_s = static_cast<double>(ms) / 1000.0;
    std::printf("%s: quantum %u cycles, %.0f ms simulated in %.3f s: %.1f sim-MHz, %.1fx real time\n", argv[1],
                cfg.quantum_cycles, sim_s * 1000.0, wall_s, static_cast<double>(avr.cycle()) / wall_s / 1e6,
                sim_s / wall_s);
    return 0;
}
