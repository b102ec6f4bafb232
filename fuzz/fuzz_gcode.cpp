// libFuzzer harness: a G-code job through the interpreter (both policies), the soft limits, and the host planner
// of each architecture: fpga-uart's CAM (and its steps file written and read back), the atmega PC program's plan
// (its bytes and motion segments) and the spi-fpga trajectory planner (sampled as the servo thread samples it),
// planned both whole and as it is read (PlanFeed), which must agree bit for bit.
// Only cnc::BadInput may leave the library code; anything else (another exception, a sanitizer report, a
// broken invariant below) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "host/core/cad2g/plan.hpp"
#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"
#include "host/core/planner/plan_feed.hpp"
#include "host/core/planner/planner.hpp"
#include "host/core/soft_limits.hpp"
#include "host/core/steps_file.hpp"

namespace {

using namespace cnc::host;

// Bounds on what the planners get, so that an execution stays in milliseconds: a job legitimately takes time in
// proportion to its length (X1e12 is a long job, not a hang). The travel keeps every coordinate, arc radius and
// chord count within a desktop machine (a 300 mm axis, as the shipped scenarios' machines); the move count keeps
// the planners' work per input small.
constexpr double kTravelMm = 300.0;
constexpr std::size_t kMaxMoves = 200;

MachineModel fuzz_machine() {
    MachineModel m;  // seed 000 reference axes: 160 steps/mm
    m.x.travel_mm = kTravelMm;
    m.y.travel_mm = kTravelMm;
    return m;
}

void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "invariant broken: %s\n", what);
        std::abort();
    }
}

void fpga_uart_cam(const Program& program, const MachineModel& machine) {
    std::vector<MotionSegment> segments;
    try {
        segments = cam(program, machine, CamOptions{});
    } catch (const cnc::BadInput&) {
        return;
    }
    std::stringstream file;
    write_steps_file(file, segments);
    const std::vector<MotionSegment> back = read_steps_file(file, "fuzz.steps");
    check(back.size() == segments.size(), "steps file round trip keeps the row count");
    for (std::size_t i = 0; i < back.size(); ++i) {
        check(back[i].steps_x == segments[i].steps_x && back[i].steps_y == segments[i].steps_y &&
                  back[i].feed == segments[i].feed && back[i].motion == segments[i].motion,
              "steps file round trip keeps steps, feed and motion");
    }
}

// Every avr.variant: the rounded words and Timer1's 16-bit word take other paths through the planner.
void atmega_pc_program(const Program& program, const MachineModel& machine) {
    for (const cad2g::Variant variant : {cad2g::Variant::Seed, cad2g::Variant::Rounded, cad2g::Variant::Timer1Y}) {
        cad2g::PcOptions opt;
        opt.variant = variant;
        cad2g::Plan plan;
        try {
            plan = cad2g::plan_program(program, machine, opt);
        } catch (const cnc::BadInput&) {
            return;
        }
        (void)cad2g::transfers(plan);
        (void)cad2g::motion_segments(plan, machine);
    }
}

bool same_sample(const planner::Sample& a, const planner::Sample& b) {
    return a.t_s == b.t_s && a.pos_mm.x_mm == b.pos_mm.x_mm && a.pos_mm.y_mm == b.pos_mm.y_mm &&
           a.vel_mm_per_s.x_mm == b.vel_mm_per_s.x_mm && a.vel_mm_per_s.y_mm == b.vel_mm_per_s.y_mm &&
           a.path_speed_mm_per_s == b.path_speed_mm_per_s && a.move == b.move;
}

// The servo's reading of the job (sim/systems/spi_fpga): samples in time order, each move's window as the laser bit
// asks for it, what lies behind dropped.
void read_as_fed(const std::string& text, const planner::PlannerConfig& cfg, const planner::Trajectory& whole) {
    std::istringstream in(text);
    planner::PlanFeed feed(cfg, std::make_unique<GcodeStream>(in, "fuzz.nc", InterpreterOptions{}, false));
    const double duration_s = whole.duration_s();
    constexpr int kSamples = 64;
    for (int i = 0; i <= kSamples; ++i) {
        const double t_s = duration_s * i / kSamples;
        check(same_sample(feed.at(t_s), whole.at(t_s)), "the fed plan samples as the whole plan");
        feed.drop_before(t_s);
    }
    const auto& windows = whole.move_windows();
    for (std::size_t i = 0; i < windows.size(); ++i) {
        const planner::FedMove* m = feed.move(i);
        check(m != nullptr && m->window == windows[i], "the fed plan's move windows as the whole plan's");
        feed.drop_moves_before(i);
    }
    check(feed.move(windows.size()) == nullptr, "the fed plan has the whole plan's moves");
}

void spi_fpga_planner(const std::string& text, const Program& program, const MachineModel& machine,
                      planner::Profile profile, planner::BlendMode mode) {
    planner::PlannerConfig cfg;
    cfg.x = machine.x.limits;
    cfg.y = machine.y.limits;
    cfg.profile = profile;
    cfg.mode = mode;
    planner::Trajectory t;
    try {
        t = planner::plan(program, cfg);
    } catch (const cnc::BadInput&) {
        return;
    }
    const double duration_s = t.duration_s();
    check(std::isfinite(duration_s) && duration_s >= 0.0, "trajectory duration finite");
    constexpr int kSamples = 64;
    for (int i = 0; i <= kSamples; ++i) {
        const planner::Sample s = t.at(duration_s * i / kSamples);
        check(std::isfinite(s.pos_mm.x_mm) && std::isfinite(s.pos_mm.y_mm), "trajectory sample finite");
    }
    read_as_fed(text, cfg, t);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const MachineModel machine = fuzz_machine();
    InterpreterOptions strict;
    strict.policy = GcodePolicy::Strict;
    try {
        std::istringstream in(text);
        (void)interpret(in, "fuzz.nc", strict);
    } catch (const cnc::BadInput&) {
    }
    Program program;
    try {
        std::istringstream in(text);
        program = interpret(in, "fuzz.nc", InterpreterOptions{});
        check_soft_limits(program, machine);
    } catch (const cnc::BadInput&) {
        return 0;
    }
    if (program.moves.size() > kMaxMoves) return 0;
    fpga_uart_cam(program, machine);
    atmega_pc_program(program, machine);
    spi_fpga_planner(text, program, machine, planner::Profile::Trapezoidal, planner::BlendMode::Continuous);
    spi_fpga_planner(text, program, machine, planner::Profile::JerkLimited, planner::BlendMode::ExactStop);
    return 0;
}
