// Scenario keys of the fpga-uart architecture (seed 000): the host's link and program (serial_host: [link] and
// host.settle_s .. host.on_timeout), the CAM that turns the job into packets (host.chord_*, host.feed_rounding,
// host.correct_rapid_feed), what the host sends (host.numerator, host.allow_feed_zero) and the FPGA ([fpga]).
#pragma once
#include "architectures/architecture.hpp"
#include "architectures/oscillator/oscillator_settings.hpp"
#include "architectures/rtl/rtl_settings.hpp"
#include "architectures/serial_host/serial_host_settings.hpp"
#include "fpga/core/fpga_config.hpp"
#include "host/core/cam.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct FpgaUartSettings final : ArchSettings {
    SerialHostSettings serial;
    host::CamOptions cam;
    bool numerator_from_machine = true;  // false: send_steps.py's constant NUMERATOR
    bool allow_feed_zero = false;        // a steps file's FeedRate 0 sent as the appendix RTL would run it
    fpga::FpgaConfig fpga;
    double ramp_start_mm_per_s = 5.0;  // with fpga.ramp: the speed each move starts and ends at
    double laser_s_max = 1000.0;       // with fpga.laser_pwm: the S of full power
    OscillatorSettings clock;  // CLOCK_50's oscillator
    RtlSettings rtl;           // the FPGA as event-driven blocks or as Verilog in the loop
};

// Reads and validates the keys (registering their documentation): BadInput naming the key for a value the FPGA's
// registers cannot hold. Verilog paths are resolved against the scenario's folder `base`.
void read_fpga_uart_settings(KeyReader& r, const std::filesystem::path& base, FpgaUartSettings& s);

}  // namespace cnc::sim
