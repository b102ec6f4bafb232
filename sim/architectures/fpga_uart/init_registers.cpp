#include "architectures/fpga_uart/init_registers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "fpga/core/step_ramp.hpp"
#include "host/core/cam.hpp"
#include "host/core/packet_codec.hpp"

namespace cnc::sim::fpga_uart {

namespace {

// send_steps.py hard-codes NUMERATOR_X = NUMERATOR_Y = 18_750_000 (seed 000 App. A.2).
constexpr std::uint32_t kSeedScriptNumerator = 18'750'000;

// `value` in the 32-bit register, or cnc::BadInput naming the key that set it.
std::uint32_t to_register(double value, const Scenario& s, const std::string& key, const char* what) {
    const double rounded = std::round(value);
    if (rounded >= 1.0 && rounded <= std::numeric_limits<std::uint32_t>::max()) {
        return static_cast<std::uint32_t>(rounded);
    }
    throw BadInput(s.file + ": " + key,
                   fmt::format(FMT_STRING("the FPGA ramp's {} register would hold {:.6g} (allowed 1 .. 4294967295)"),
                               what, value));
}

// The smaller of the axes' limits in steps (per s^2 or s^3), and the key that sets it: in steps of its own axis, so
// that either axis dominant stays within its own limit (the other axis follows at a fraction of the dominant one's
// rate).
struct SlowerAxis {
    double steps = 0.0;
    std::string key;
};

SlowerAxis slower_axis(const host::MachineModel& m, double host::AxisLimits::*limit, const char* name) {
    const double x = m.x.limits.*limit * m.x.steps_per_mm();
    const double y = m.y.limits.*limit * m.y.steps_per_mm();
    return x <= y ? SlowerAxis{x, std::string("machine.x.") + name} : SlowerAxis{y, std::string("machine.y.") + name};
}

// The ramp's registers: the acceleration the slower axis allows and the start speed, in steps of the axis with
// fewer steps per mm.
void ramp_registers(const Scenario& s, const FpgaUartSettings& f, InitRegisters& r) {
    const host::MachineModel& m = s.machine;
    const SlowerAxis accel = slower_axis(m, &host::AxisLimits::max_accel_mm_per_s2, "max_accel_mm_per_s2");
    const double clk_hz = f.fpga.clk_hz;
    r.ramp_accel =
        to_register(accel.steps * std::ldexp(1.0, fpga::kPhaseBits) / (clk_hz * clk_hz), s, accel.key, "acceleration");
    const double start_steps_per_s = f.ramp_start_mm_per_s * std::min(m.x.steps_per_mm(), m.y.steps_per_mm());
    r.ramp_start = to_register(start_steps_per_s * std::ldexp(1.0, fpga::kPhaseBits - fpga::kStartShift) / clk_hz, s,
                               "fpga.ramp_start_mm_per_s", "start speed");
}

// The S-curve's jerk register, of the slower axis as the acceleration. Its 32 bits at 2^-80 steps per clock^3 hold
// up to 4.4e8 steps/s^3 at 50 MHz: a jerk phase of the slowest acceleration register (1) lasts 2^32 / jerk >= 1
// clock, so a jerk the register holds never makes a jerk phase shorter than a clock.
void jerk_register(const Scenario& s, const FpgaUartSettings& f, InitRegisters& r) {
    const SlowerAxis jerk = slower_axis(s.machine, &host::AxisLimits::max_jerk_mm_per_s3, "max_jerk_mm_per_s3");
    const double clk_hz = f.fpga.clk_hz;
    r.ramp_jerk =
        to_register(jerk.steps * std::ldexp(1.0, fpga::kPhaseBits + fpga::kJerkShift) / (clk_hz * clk_hz * clk_hz), s,
                    jerk.key, "jerk");
}

}  // namespace

InitRegisters init_registers(const Scenario& s, const FpgaUartSettings& f) {
    InitRegisters r;
    if (f.numerator_from_machine) {
        r.num_x = host::numerator(s.machine.x.steps_per_mm(), f.fpga.clk_hz);
        r.num_y = host::numerator(s.machine.y.steps_per_mm(), f.fpga.clk_hz);
    } else {
        r.num_x = r.num_y = kSeedScriptNumerator;
    }
    if (f.fpga.ramp != fpga::StepRamp::None) ramp_registers(s, f, r);
    if (f.fpga.ramp == fpga::StepRamp::SCurve) jerk_register(s, f, r);
    return r;
}

std::vector<std::uint8_t> init_packet(const InitRegisters& r, const FpgaUartSettings& f) {
    if (f.fpga.ramp == fpga::StepRamp::None) {
        const host::InitBytes b = host::encode_init(r.num_x, r.num_y);
        return {b.begin(), b.end()};
    }
    if (f.fpga.ramp == fpga::StepRamp::SCurve) {
        const host::ScurveInitBytes b =
            host::encode_scurve_init(r.num_x, r.num_y, r.ramp_accel, r.ramp_start, r.ramp_jerk);
        return {b.begin(), b.end()};
    }
    const host::RampInitBytes b = host::encode_ramp_init(r.num_x, r.num_y, r.ramp_accel, r.ramp_start);
    return {b.begin(), b.end()};
}

fpga::MoveInputs move_inputs(std::int32_t steps_x, std::int32_t steps_y, std::uint16_t feed, const InitRegisters& r) {
    return {steps_x, steps_y, feed, r.num_x, r.num_y, r.ramp_accel, r.ramp_start, r.ramp_jerk};
}

}  // namespace cnc::sim::fpga_uart
