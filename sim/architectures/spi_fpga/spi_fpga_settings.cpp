#include "architectures/spi_fpga/spi_fpga_settings.hpp"

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "architectures/planner/planner_settings.hpp"
#include "common/bad_input.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::sim {

namespace {

TimePs us_to_ps(double us) {
    return static_cast<TimePs>(us * static_cast<double>(kPsPerUs) + 0.5);
}
TimePs ns_to_ps(double ns) {
    return static_cast<TimePs>(ns * static_cast<double>(kPsPerNs) + 0.5);
}

void read_servo(KeyReader& r, host::servo::ServoConfig& c) {
    c.period_ps = us_to_ps(r.get_float("host.servo_period_us", 1000.0, 1.0, 100'000.0,
                                       "servo thread period, us (LinuxCNC default 1 ms; seed 004 §4.1 gives none)"));
    c.latency.max_ps = us_to_ps(r.get_float("host.latency_max_us", 50.0, 0.0, 100'000.0,
                                            "bound of the servo thread's wake-up latency, us (LinuxCNC latency "
                                            "test: < 50 us OK on PREEMPT_RT); 0: exact wake-ups"));
    c.latency.distribution = host::servo::latency_distribution_from(
        r.get_choice("host.latency_distribution", "exponential", {"exponential", "uniform"},
                     "wake-up latency: exponential of scale max/5 truncated at the bound (cyclictest-like), or "
                     "uniform up to the bound"));
    c.position_gain = r.get_float("host.position_gain", c.position_gain, 0.001, 1.0,
                                  "share of the predicted position error the stepgen law corrects per period "
                                  "(hm2 stepgen: 0.5)");
    c.deadband_steps = r.get_float("host.deadband_steps", c.deadband_steps, 0.0, 1000.0,
                                   "position error the law leaves to the feed-forward alone, steps (Remora: 1)");
    c.stepgen_margin = r.get_float("host.stepgen_margin", c.stepgen_margin, 0.0, 10.0,
                                   "stepgen velocity/acceleration limits above the planner's axis limits, as a "
                                   "fraction (pncconf: 0.25)");
}

void read_link(KeyReader& r, spi::SpiConfig& c) {
    c.sclk_hz = static_cast<std::uint32_t>(r.get_int("spi.sclk_hz", c.sclk_hz, 1, 100'000'000,
                                                     "SPI clock, Hz (250 MHz / 50: a Raspberry Pi rate the "
                                                     "FPGA's oversampling slave can follow)"));
    c.cs_setup_ps = ns_to_ps(r.get_float("spi.cs_setup_ns", 1000.0, 0.0, 1e6, "SS fall to the first SCLK rise, ns"));
    c.cs_hold_ps = ns_to_ps(r.get_float("spi.cs_hold_ns", 1000.0, 0.0, 1e6, "end of the last bit cell to SS rise, ns"));
    c.ss_idle_min_ps =
        ns_to_ps(r.get_float("spi.ss_idle_ns", 1000.0, 0.0, 1e6, "least SS-high time between frames, ns"));
    c.trace_wires = r.get_bool("spi.trace_wires", false,
                               "toggle SCLK/MOSI/MISO/SS bit by bit (and trace them in the VCD); false: one "
                               "transaction per frame at the same SS edges, and the wires are driven only when "
                               "trace.signals names one of them");
}

void read_fpga(KeyReader& r, fpga::SpiFpgaConfig& c) {
    c.clk_hz = static_cast<std::uint32_t>(r.get_int("fpga_spi.clock_hz", c.clk_hz, 1'000'000, 500'000'000,
                                                    "FPGA clock, Hz; must divide 1e12 (seed 000's board: 50 MHz)"));
    c.fifo_depth = static_cast<std::uint32_t>(
        r.get_int("fpga_spi.fifo_depth", c.fifo_depth, 1, 1024, "rate frames the FIFO holds (seed 004 §5.1.2)"));
    c.pulse_cycles = static_cast<std::uint32_t>(r.get_int("fpga_spi.pulse_cycles", c.pulse_cycles, 1, 1'000'000,
                                                          "STEP high time, clocks (seed 004 §5.1.3 duration)"));
    c.dir_setup_cycles = static_cast<std::uint32_t>(r.get_int("fpga_spi.dir_setup_cycles", c.dir_setup_cycles, 1,
                                                              1'000'000, "DIR change to the next STEP rise, clocks"));
    c.dir_hold_cycles = static_cast<std::uint32_t>(
        r.get_int("fpga_spi.dir_hold_cycles", c.dir_hold_cycles, 1, 1'000'000, "STEP rise to a DIR change, clocks"));
    c.rate_apply = r.get_choice("fpga_spi.rate_apply", "immediately", {"at-next-pulse", "immediately"},
                                "when a new rate word governs: at the running period's end (one FIFO frame per "
                                "STEP), or one clock after it is written") == "at-next-pulse"
                       ? fpga::RateApply::AtNextPulse
                       : fpga::RateApply::Immediately;
}

// The models' own checks name their fields ("spi: sclk_hz"); report them under the scenario key.
template <typename Check>
void checked(KeyReader& r, const std::vector<std::pair<std::string, std::string>>& keys, Check&& check) {
    try {
        check();
    } catch (const BadInput& e) {
        const std::string what = e.what();
        for (const auto& [field, key] : keys) {
            if (what.find(field) != std::string::npos) r.fail(key, what);
        }
        throw;
    }
}

const std::vector<std::pair<std::string, std::string>> kLinkKeys = {{"spi: sclk_hz", "spi.sclk_hz"},
                                                                    {"spi: cs_setup_ps", "spi.cs_setup_ns"},
                                                                    {"spi: cs_hold_ps", "spi.cs_hold_ns"},
                                                                    {"spi: ss_idle_min_ps", "spi.ss_idle_ns"}};
const std::vector<std::pair<std::string, std::string>> kFpgaKeys = {
    {"fpga: clk_hz", "fpga_spi.clock_hz"},
    {"fpga: fifo_depth", "fpga_spi.fifo_depth"},
    {"fpga: pulse_cycles", "fpga_spi.pulse_cycles"},
    {"fpga: dir_setup_cycles", "fpga_spi.dir_setup_cycles"},
    {"fpga: dir_hold_cycles", "fpga_spi.dir_hold_cycles"}};

// The servo period must hold one transfer slot; the latency bound plus a slot must fit in it too, or a late
// wake-up would still be transferring when the next period's frame is due (and a landing pulse, servo_core.hpp,
// could give two steps).
void check_period(KeyReader& r, const SpiFpgaSettings& s) {
    const std::size_t bits = spi::frame_bits(host::servo::kAxes);
    try {
        spi::check_transfer_fits(s.link, bits, s.servo.period_ps);
    } catch (const BadInput& e) {
        std::string what = e.what();
        const std::string field = "spi: sclk_hz: ";  // the link model's own name for the key, replaced by ours
        if (what.rfind(field, 0) == 0) what.erase(0, field.size());
        r.fail(r.has("spi.sclk_hz") && !r.has("host.servo_period_us") ? "spi.sclk_hz" : "host.servo_period_us", what);
    }
    const TimePs slot = spi::transfer_slot_ps(s.link, bits);
    if (s.servo.latency.max_ps + slot > s.servo.period_ps) {
        std::ostringstream m;
        m << "a wake-up latency of up to " << ps_to_us(s.servo.latency.max_ps) << " us plus the " << ps_to_us(slot)
          << " us SPI transfer slot (" << bits << "-bit frame at " << s.link.sclk_hz << " Hz) exceeds the "
          << ps_to_us(s.servo.period_ps)
          << " us servo period: the latency bound must stay below the period minus the transfer ("
          << ps_to_us(s.servo.period_ps - slot) << " us)";
        r.fail("host.latency_max_us", m.str());
    }
}

}  // namespace

// seed 004 §5.1.4 names the iCE40 HX8K but not its board; the model keeps a 50 MHz clock (fpga_spi.clock_hz).
constexpr OscillatorPart kFpgaBoardClock{
    "fpga_spi", "50 MHz crystal oscillator of the FPGA board (seed 004 names none)",
    50.0,       "the common +-50 ppm grade of 50 MHz CMOS crystal oscillators",
    3.0,        "such an oscillator's period jitter is a few ps rms; 3 ps of phase jitter"};

void read_spi_fpga_settings(KeyReader& r, const std::filesystem::path& base, SpiFpgaSettings& s,
                            const host::MachineModel& machine) {
    read_planner_settings(r, machine, s.planner);
    read_servo(r, s.servo);
    read_link(r, s.link);
    read_fpga(r, s.fpga);
    read_oscillator_settings(r, kFpgaBoardClock, s.fpga.clk_hz, s.clock);
    read_rtl_settings(r, base, "fpga_spi", s.rtl);
    // Our Verilog counts the FIFO's frames in 8-bit registers.
    constexpr std::uint32_t kRtlMaxFifoDepth = 255;
    if (s.rtl.rtl && s.rtl.design.top_file.empty() && s.fpga.fifo_depth > kRtlMaxFifoDepth) {
        r.fail("fpga_spi.fifo_depth", "spi_fpga_top.v holds at most " + std::to_string(kRtlMaxFifoDepth) +
                                          " frames (fpga.model = \"rtl\")");
    }
    checked(r, kLinkKeys, [&] { spi::validate(s.link); });
    checked(r, kFpgaKeys, [&] { fpga::validate(s.fpga); });
    checked(r, kLinkKeys, [&] { fpga::check_link(s.link, s.fpga); });
    check_period(r, s);
    s.servo.clk_hz = s.fpga.clk_hz;
    s.servo.min_period_cycles = fpga::min_period_cycles(s.fpga);
}

void check_rate_limits(const SpiFpgaSettings& s, const host::MachineModel& machine, const std::string& file) {
    const std::pair<const char*, double> axes[] = {{"x", machine.x.steps_per_mm()}, {"y", machine.y.steps_per_mm()}};
    const host::planner::AxisLimits* limits[] = {&s.planner.x, &s.planner.y};
    for (std::size_t a = 0; a < 2; ++a) {
        const double mm_per_s = limits[a]->max_velocity_mm_per_s * (1.0 + s.servo.stepgen_margin);
        const double steps_per_s = mm_per_s * axes[a].second;
        try {
            (void)spi::period_for_rate(steps_per_s, s.fpga.clk_hz, fpga::min_period_cycles(s.fpga));
        } catch (const BadInput& e) {
            std::ostringstream m;
            m << "the stepgen velocity limit " << mm_per_s << " mm/s (this limit x (1 + host.stepgen_margin "
              << s.servo.stepgen_margin << ")) at " << axes[a].second
              << " steps/mm overflows the rate word: " << e.what();
            throw BadInput(file + ": machine." + axes[a].first + ".max_velocity_mm_per_s", m.str());
        }
    }
}

}  // namespace cnc::sim
