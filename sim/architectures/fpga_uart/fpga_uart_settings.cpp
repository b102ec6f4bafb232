#include "architectures/fpga_uart/fpga_uart_settings.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "common/queue_protocol.hpp"
#include "fpga/core/laser_pwm.hpp"
#include "fpga/core/rtl_design.hpp"

namespace cnc::sim {

namespace {

// The FPGA model refuses values its RTL registers cannot hold; name the scenario key that set them.
void check_fpga(const KeyReader& r, const fpga::FpgaConfig& cfg) {
    try {
        fpga::validate(cfg);
    } catch (const BadInput& e) {
        const std::string what = e.what();
        const std::pair<const char*, const char*> keys[] = {{"clk_hz", "fpga.clock_hz"},
                                                            {"uart_full_bit_cycles", "fpga.uart_baud"},
                                                            {"uart_half_bit_cycles", "fpga.uart_baud"},
                                                            {"watchdog_cycles", "fpga.watchdog_ms"},
                                                            {"pulse_high_cycles", "fpga.pulse_high_cycles"},
                                                            {"dir_settle_cycles", "fpga.dir_settle_cycles"}};
        for (const auto& [field, key] : keys) {
            if (what.find(field) != std::string::npos) r.fail(key, what);
        }
        throw;
    }
}

void read_host(KeyReader& r, FpgaUartSettings& s) {
    s.allow_feed_zero = r.get_bool("host.allow_feed_zero", false,
                                   "send FeedRate 0 from a steps file as the appendix allows (step_gen then uses "
                                   "62500 clocks per step on both axes); false: refused, as the text requires");
    s.numerator_from_machine =
        r.get_choice("host.numerator", "machine", {"machine", "seed-constant"},
                     "init packet NUMERATOR: from the machine model, or send_steps.py's constant 18750000") ==
        "machine";
    s.cam.chord_tolerance_mm = r.get_float("host.chord_tolerance_mm", s.cam.chord_tolerance_mm, 1e-6, 10.0,
                                           "max distance of an arc chord from the arc, mm");
    s.cam.chord_ends = r.get_choice("host.chord_ends", "on-arc", {"on-arc", "round"},
                                    "chord end points: the grid point nearest the arc, or each axis rounded "
                                    "(seed 000 sec. 3.4.4)") == "on-arc"
                           ? host::ChordEnds::OnArc
                           : host::ChordEnds::Round;
    s.cam.feed_rounding = r.get_choice("host.feed_rounding", "round", {"round", "truncate"},
                                       "packet feed from the dominant-axis feed") == "round"
                              ? host::FeedRounding::Round
                              : host::FeedRounding::Truncate;
    s.cam.correct_rapid_feed =
        r.get_bool("host.correct_rapid_feed", s.cam.correct_rapid_feed, "G0 feed reduced to the dominant axis like G1");
}

void read_fpga(KeyReader& r, fpga::FpgaConfig& cfg) {
    cfg.clk_hz = static_cast<std::uint32_t>(
        r.get_int("fpga.clock_hz", cfg.clk_hz, 1'000'000, 500'000'000, "FPGA clock, Hz (CLOCK_50)"));
    const auto fpga_baud = r.get_int("fpga.uart_baud", 115'200, 300, 10'000'000,
                                     "baud rate the FPGA UART was built for (bit = clock/baud cycles)");
    cfg.uart_full_bit_cycles = static_cast<std::uint32_t>(cfg.clk_hz / fpga_baud);
    cfg.uart_half_bit_cycles = cfg.uart_full_bit_cycles / 2;
    cfg.watchdog_cycles = static_cast<std::uint32_t>(
        r.get_float("fpga.watchdog_ms", 100.0, 0.001, 10000.0, "packet_decoder inter-byte watchdog, ms") * 1e-3 *
        cfg.clk_hz);
    cfg.pulse_high_cycles = static_cast<std::uint32_t>(
        r.get_int("fpga.pulse_high_cycles", cfg.pulse_high_cycles, 1, 1'000'000, "STEP high time, clocks"));
    cfg.dir_settle_cycles = static_cast<std::uint32_t>(
        r.get_int("fpga.dir_settle_cycles", cfg.dir_settle_cycles, 1, 511, "DIR to first STEP wait, clocks"));
    cfg.init_packet_wired = r.get_bool("fpga.init_packet_wired", cfg.init_packet_wired,
                                       "init packet reaches step_gen (false: appendix top.v leaves it open)");
    cfg.period_arithmetic = r.get_choice("fpga.period_arithmetic", "exact", {"exact", "wrap32"},
                                         "subordinate period product: exact, or the appendix's 32-bit wrap") == "exact"
                                ? fpga::PeriodArithmetic::Exact
                                : fpga::PeriodArithmetic::Wrap32;
    check_fpga(r, cfg);
}

// Our option on seed 000 §7.2's "checksum or CRC field in packets": the frames are in host/core/packet_codec.hpp.
void read_packet_check(KeyReader& r, FpgaUartSettings& s) {
    host::PacketCheckConfig& c = s.serial.sender.check;
    c.crc = r.get_choice("protocol.crc", "none", {"none", "crc16"},
                         "packet check (seed 000 sec. 7.2 proposes one): none, the seed's packets; crc16, each packet "
                         "followed by its CRC-16/CCITT-FALSE and a motion packet's first byte carrying an alternating "
                         "sequence bit, the FPGA answering a bad CRC with NAK 0x55 and a repeated move with its ACK, "
                         "the host sending a packet again after a NAK or a timeout") == "crc16";
    c.retries = static_cast<int>(r.get_int("protocol.retries", c.retries, 0, 1000,
                                           "with protocol.crc: sends of a packet after its first before the ACK "
                                           "timeout counts as the seed's (host.on_timeout)"));
    c.retry_delay_ps = s_to_ps(1e-3 * r.get_float("protocol.retry_delay_ms", ps_to_s(c.retry_delay_ps) * 1e3, 0.0, 1e5,
                                                  "with protocol.crc: wait before a packet is sent again, ms (above "
                                                  "fpga.watchdog_ms, so that the FPGA has dropped a partial packet)"));
    s.fpga.packet_crc = c.crc;
}

// Our option on seed 000 §7.2's command queue and FIFO packet buffer: the frame in common/queue_protocol.hpp.
void read_queue(KeyReader& r, FpgaUartSettings& s) {
    s.fpga.queue_depth = static_cast<int>(
        r.get_int("fpga.queue_depth", 0, 0, queue_protocol::kMaxDepth,
                  "packets the FPGA queues ahead of step_gen (seed 000 sec. 7.2 proposes a command queue): 0, the "
                  "seed's stop-and-wait on an ACK at each move's end; 1 .. 16, numbered packets acknowledged on "
                  "receipt with the free slots, the host keeping that many in flight and sending again from the "
                  "number the FPGA expects after a refusal or a silence; needs protocol.crc = \"crc16\""));
    if (s.fpga.queue_depth == 0) return;
    if (!s.fpga.packet_crc) {
        r.fail("fpga.queue_depth",
               "the packet queue needs protocol.crc = \"crc16\": a byte lost while the host sends ahead misframes "
               "every packet behind it, and only a check finds the packet boundaries again");
    }
}

// Our option on seed 000 §7.2's trapezoidal or S-curve ramps on the FPGA: step_gen's law in fpga/core/step_ramp.hpp.
void read_ramp(KeyReader& r, FpgaUartSettings& s) {
    const std::string ramp =
        r.get_choice("fpga.ramp", "none", {"none", "trapezoidal", "s-curve"},
                     "step_gen's speed profile (seed 000 sec. 7.2 proposes trapezoidal or S-curve ramps on the FPGA): "
                     "none, the seed's, every step of a move at the packet's rate; trapezoidal, each move starts at "
                     "fpga.ramp_start_mm_per_s, speeds up at the slower axis' machine.<axis>.max_accel_mm_per_s2 to "
                     "the packet's rate and slows down to the start speed at its end, the host sending both in a "
                     "17-byte init packet; s-curve, the same with the acceleration changing at the slower axis' "
                     "machine.<axis>.max_jerk_mm_per_s3 (21-byte init packet)");
    s.fpga.ramp = ramp == "s-curve"       ? fpga::StepRamp::SCurve
                  : ramp == "trapezoidal" ? fpga::StepRamp::Trapezoidal
                                          : fpga::StepRamp::None;
    s.ramp_start_mm_per_s = r.get_float("fpga.ramp_start_mm_per_s", s.ramp_start_mm_per_s, 0.001, 1000.0,
                                        "with fpga.ramp: the speed a move starts and ends at, mm/s (a stepper starts "
                                        "without losing steps below its pull-in speed: cncsim motor-curve)");
    if (s.fpga.ramp == fpga::StepRamp::None) return;
    if (s.rtl.rtl && s.fpga.ramp == fpga::StepRamp::SCurve) {
        r.fail("fpga.ramp",
               "the S-curve is in the event model only (fpga.model = \"event\"; the Verilog has \"trapezoidal\"): its "
               "per-move plan searches the velocity gain by bisection, each try a square root and an 80-bit division, "
               "thousands of clocks where DIR_WAIT leaves fpga.dir_settle_cycles (200) before the first step");
    }
    if (s.rtl.rtl && s.fpga.dir_settle_cycles < fpga::kRtlRampDirSettleMin) {
        r.fail("fpga.dir_settle_cycles",
               fmt::format(FMT_STRING("{} clocks: with fpga.ramp and fpga.model = \"rtl\" it must be at least {} (the "
                                      "Verilog divides the ramp's cruise speed during DIR_WAIT)"),
                           s.fpga.dir_settle_cycles, fpga::kRtlRampDirSettleMin));
    }
    if (!s.fpga.init_packet_wired) {
        r.fail("fpga.ramp", "the ramp's registers come in the init packet: it needs fpga.init_packet_wired = true");
    }
}

// Our option on seed 000 §7.2's "e-stop and interlock inputs"; the scenario's [[events]] drive them.
void read_safety_inputs(KeyReader& r, FpgaUartSettings& s) {
    s.fpga.estop_input = r.get_bool(
        "fpga.estop", false,
        "an e-stop input on the FPGA (seed 000 sec. 7.2 proposes one), pressed by an [[events]] estop-pressed: two "
        "clocks through its synchroniser it halts step_gen (STEP and busy low, no packet run after) and the laser "
        "follows busy a clock later, and uart_tx sends the host 0x4B, which aborts the script; latched until reset");
    s.fpga.interlock_input = r.get_bool(
        "fpga.interlock", false,
        "an interlock input on the FPGA for the laser's lid (seed 000 sec. 7.2), driven by [[events]] lid-opened and "
        "lid-closed: while the lid is open the laser is held off (three clocks after the input at most), the motion "
        "goes on");
}

// Our option on seed 000 §7.2's PWM laser power: laser_ctrl's law in fpga/core/laser_pwm.hpp, the frame in
// host/core/packet_codec.hpp.
void read_laser_pwm(KeyReader& r, FpgaUartSettings& s) {
    const bool on = r.get_bool(
        "fpga.laser_pwm", false,
        "PWM laser power (seed 000 sec. 7.2 proposes it): each motion packet carries a PWM high time of S / "
        "fpga.laser_s_max of the period after FeedRate (13 bytes, 15 with the CRC), and laser_ctrl drives the laser "
        "pin with that duty at fpga.laser_pwm_hz while a cut runs; false, the seed's laser, on for the whole cut");
    // grbl 1.1's laser mode drives the same diode-laser drivers from Timer2's fast PWM at prescaler 8: 16 MHz / 8 /
    // 256 = 7812.5 Hz, 6400 clocks of 50 MHz.
    const double pwm_hz = r.get_float("fpga.laser_pwm_hz", 7812.5, 1000.0, 50000.0,
                                      "with fpga.laser_pwm: the PWM frequency, Hz; fpga.clock_hz / it must be a whole "
                                      "number of clocks (default: grbl 1.1's 7812.5 Hz on OC2A)");
    s.laser_s_max = r.get_float("fpga.laser_s_max", s.laser_s_max, 1.0, 65535.0,
                                "with fpga.laser_pwm: the S word of full power, duty 100 % (grbl's $30 default: "
                                "1000); a larger S is held to it");
    if (!on) return;
    const std::optional<std::uint32_t> period = fpga::laser_pwm_period_cycles(s.fpga.clk_hz, pwm_hz);
    if (!period) {
        const double cycles = static_cast<double>(s.fpga.clk_hz) / pwm_hz;
        r.fail("fpga.laser_pwm_hz",
               fmt::format(FMT_STRING("{} Hz is not reachable from the {} Hz FPGA clock: the period must be a whole "
                                      "number of clocks (fpga.clock_hz / Hz = {:.4f}); e.g. {:.3f} Hz ({} clocks)"),
                           pwm_hz, s.fpga.clk_hz, cycles, static_cast<double>(s.fpga.clk_hz) / std::round(cycles),
                           std::round(cycles)));
    }
    if (*period > 65535) {
        r.fail("fpga.laser_pwm_hz",
               fmt::format(FMT_STRING("{} Hz is {} clocks of the {} Hz FPGA clock: laser_ctrl's 16-bit count reaches "
                                      "65535 clocks"),
                           pwm_hz, *period, s.fpga.clk_hz));
    }
    s.fpga.laser_pwm_period_cycles = *period;
}

}  // namespace

// seed 000 §5.1.1: the DE1-SoC's CLOCK_50.
constexpr OscillatorPart kDe1SocClock50{
    "fpga", "50 MHz crystal oscillator of the DE1-SoC (CLOCK_50)",
    50.0,   "the DE1-SoC manual names no part: the common +-50 ppm grade of 50 MHz CMOS crystal oscillators",
    3.0,    "such an oscillator's period jitter is a few ps rms; 3 ps of phase jitter"};

void read_fpga_uart_settings(KeyReader& r, const std::filesystem::path& base, FpgaUartSettings& s) {
    read_serial_host_settings(r, s.serial);
    read_host(r, s);
    read_fpga(r, s.fpga);
    read_oscillator_settings(r, kDe1SocClock50, s.fpga.clk_hz, s.clock);
    read_rtl_settings(r, base, "fpga", s.rtl);
    read_packet_check(r, s);
    read_queue(r, s);
    read_ramp(r, s);
    read_safety_inputs(r, s);
    read_laser_pwm(r, s);
}

}  // namespace cnc::sim
