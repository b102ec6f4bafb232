#include "host/core/soft_limits.hpp"

#include <tuple>

#include <fmt/format.h>

#include "common/bad_input.hpp"

namespace cnc::host {

namespace {

// Arc extremes and inch conversions carry floating-point rounding; 1 nm is far below a microstep (6.25 um at
// 160 steps/mm), so a move that ends exactly on the travel is not refused for it.
constexpr double kRoundingMm = 1e-6;

constexpr const char* kHowToTurnOff = " (soft limits; machine.soft_limits = false turns them off)";

}  // namespace

std::optional<std::string> soft_limit_breach(const MachineModel& machine, MachineAxis axis, double lo_mm,
                                             double hi_mm) {
    const bool x = axis == MachineAxis::X;
    const double travel_mm = (x ? machine.x : machine.y).travel_mm;
    if (!machine.soft_limits || travel_mm <= 0.0) return std::nullopt;  // travel 0: unlimited
    const std::string name = x ? "X " : "Y ";
    const std::string key = x ? "machine.x.travel_mm" : "machine.y.travel_mm";
    if (hi_mm > travel_mm + kRoundingMm) {
        return fmt::format(FMT_STRING("{}{:.10g} mm is past {} = {:.10g}{}"), name, hi_mm, key, travel_mm,
                           kHowToTurnOff);
    }
    if (lo_mm < -kRoundingMm) {
        return fmt::format(FMT_STRING("{}{:.10g} mm is below 0, the start of {} = {:.10g}{}"), name, lo_mm, key,
                           travel_mm, kHowToTurnOff);
    }
    return std::nullopt;
}

void check_soft_limits(const ProgrammedMove& move, const MachineModel& machine, const std::string& filename) {
    if (!machine.soft_limits) return;
    const geom::Box box = move.path.bounds();
    for (const auto& [axis, lo, hi] : {std::tuple{MachineAxis::X, box.min.x_mm, box.max.x_mm},
                                       std::tuple{MachineAxis::Y, box.min.y_mm, box.max.y_mm}}) {
        if (const auto why = soft_limit_breach(machine, axis, lo, hi)) {
            throw BadInput(filename + ":" + std::to_string(move.line), *why);
        }
    }
}

void check_soft_limits(const Program& program, const MachineModel& machine) {
    for (const ProgrammedMove& move : program.moves) check_soft_limits(move, machine, program.filename);
}

}  // namespace cnc::host
