// With the FPGA's trapezoidal ramp (fpga.ramp): the motion each move was commanded, for the metrics "with a
// planner" (docs/metrics.md). A ramped move is not the uniform motion at F from its first step that the seed's
// moves are measured against: its commanded motion is the trapezoid its registers describe, from its first step
// on, and its steps' timing is their sync error against it. Its step rate changes on every ramp step, so each step
// of a ramp is a pulse run of its own and the cruise one run (metrics::RateSegment).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "architectures/fpga_uart/init_registers.hpp"
#include "common/clock_grid.hpp"
#include "common/geometry.hpp"
#include "fpga/board.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim::fpga_uart {

// One move's trapezoid or S-curve along its dominant axis, in steps from its start: the first step rises at t0
// (position 1/2, the level a rounding quantiser steps at), the velocity climbs from the start speed to the move's
// programmed rate (or to where a short move turns round, half its steps on), holds, and falls back the same way
// (the time-mirror of the climb) to the start speed at the last step (position N - 1/2), which it keeps for the
// last half step. The trapezoid climbs at the acceleration; the S-curve's acceleration grows at the jerk for its
// jerk time, holds for its top time and falls back to zero.
class RampProfile {
public:
    // The trapezoid's climb: to the cruise, or to where a short move turns round.
    RampProfile(double steps, double start_steps_per_s, double accel_steps_per_s2, double cruise_steps_per_s);

    // The S-curve's climb as step_gen planned it (fpga/core/scurve_plan.hpp): it reaches start + jerk x jerk_s x
    // (jerk_s + top_s) and cruises there.
    struct SCurve {
        double jerk_steps_per_s3 = 0.0;
        double jerk_s = 0.0;
        double top_s = 0.0;
    };
    RampProfile(double steps, double start_steps_per_s, const SCurve& climb);

    // Position [steps] and velocity [steps/s] tau seconds after the first step (0 before it, steps after the end).
    [[nodiscard]] double position(double tau_s) const;
    [[nodiscard]] double velocity(double tau_s) const;
    [[nodiscard]] double steps() const { return m_steps; }
    [[nodiscard]] double peak_steps_per_s() const { return m_peak; }
    [[nodiscard]] double duration_s() const { return 2 * m_ramp_s + m_cruise_s + 0.5 / m_start; }

private:
    // The climb's velocity over the start speed and its integral, tau seconds into the climb (0 <= tau <= m_ramp_s).
    [[nodiscard]] double gained(double tau_s) const;
    [[nodiscard]] double gained_distance(double tau_s) const;

    double m_steps;
    double m_start;       // steps/s
    double m_accel;       // steps/s^2, the climb's top acceleration
    double m_jerk_s = 0;  // the S-curve's jerk time (0: the trapezoid)
    double m_peak;        // steps/s
    double m_ramp_s;      // each ramp's time
    double m_ramp_steps;  // each ramp's distance
    double m_cruise_s;
};

class RampCommanded {
public:
    RampCommanded(const fpga::FpgaConfig& cfg, const InitRegisters& registers, geom::Vec2 origin_mm,
                  std::array<double, 2> steps_per_mm);

    // Every packet step_gen has begun to run by now_ps (t_run_start_ps <= now_ps) that was not read yet.
    void read(const fpga::Board& fpga, TimePs now_ps);
    // The first packet record not read yet.
    [[nodiscard]] std::size_t next_record() const { return m_next_record; }

    // The trajectory of the moves read so far (shared with this object, which must outlive it), known to t_end_ps.
    [[nodiscard]] metrics::CommandedTrajectory trajectory(TimePs t_end_ps) const;
    // [axis] the rate segments of the moves read since the last call, in time order.
    [[nodiscard]] std::vector<std::vector<metrics::RateSegment>> take_segments();

private:
    struct Move {
        TimePs t0_ps = 0;
        TimePs t_end_ps = 0;
        TimePs latest_end_ps = 0;  // of this move and every one before it
        geom::Vec2 from_mm;
        geom::Vec2 travel_mm;
        RampProfile profile;
    };
    struct Moves {
        std::vector<Move> moves;
        geom::Vec2 origin_mm;
        [[nodiscard]] metrics::CommandedState at(TimePs t_ps) const;
    };

    void add(const fpga::PacketRecord& r, const ClockGrid& clock);

    fpga::FpgaConfig m_cfg;
    InitRegisters m_registers;
    std::array<double, 2> m_steps_per_mm;
    std::shared_ptr<Moves> m_moves;
    geom::Vec2 m_at_mm;  // where the moves read so far end
    std::size_t m_next_record = 0;
    std::vector<std::vector<metrics::RateSegment>> m_segments;
};

}  // namespace cnc::sim::fpga_uart
