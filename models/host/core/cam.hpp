// CAM of seed 000 §3.4-3.5 (GCODE2STEPS): programmed moves -> motion segments (one motion packet and one
// steps-file row each): arcs as chords, mm -> signed steps, and the dominant-axis feed ("NUMERATOR concept").
#pragma once
#include <cstdint>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::host {

enum class FeedRounding { Round, Truncate };  // seed 000 Q6: the host's rounding of axisFeed is unstated

// Where the interior chord ends of an arc land on the step grid (the programmed end point of the arc is always
// its own per-axis rounding, so the next move starts where the program says).
// - Round: the seed's literal rule (seed 000 §3.4.4, "each intermediate point goes through the same mm->steps
//   rounding"): llround of the ideal end point per axis. The rounded point lies up to 0.71 step off the circle.
// - OnArc: the grid point nearest the circle (smallest |distance to centre - R|, compared in mm) among the
//   grid points within +-W steps per axis of the rounded ideal end whose angle lies strictly between the
//   previous chosen end and the next ideal end (so chords stay in order and none is empty); ties go to the
//   point nearer the ideal end, then to the smaller X, then the smaller Y. W = min(3, floor(5 % of the
//   longest chord's arc length in steps)) per axis, so that a chord's span changes by ~10 % at most; when
//   W = 0 the four floor/ceil corners round the ideal end are the candidates. An end with no candidate is
//   left out (the next chord carries it, as an empty chord would be). Chords are counted for a sagitta of
//   kOnArcSagittaShare x the tolerance, so that the longer spans snapping can give stay within it.
// Why OnArc is the default: the FPGA's reference-word step generator (seed 000 §5.4) steps the subordinate
// axis at the start of its period, a staircase that adds up to one step to the path. With chord ends on the
// circle the contour error stays within the chord tolerance plus one step; with Round the end's own up to
// 0.71 step comes on top (9.6 um against 8.25 um on a radius-10 mm circle at 160 steps/mm, tolerance 0.002 mm).
enum class ChordEnds { OnArc, Round };

// Margin of ChordEnds::OnArc. The sagitta of a chord spanning angle a is R (1 - cos(a/2)) ~ R a^2 / 8, so
// counting chords for 0.8 x tol lets every span grow by 1/sqrt(0.8) - 1 = 11.8 % before its sagitta reaches
// tol. Snapping moves an end along the arc by at most its window's reach: the ideal end's rounding
// (<= 0.5 step per axis) plus W (<= 5 % of the longest chord's arc length) per axis. Where the tangent runs
// along an axis a chord therefore grows by <= 10 % + 1 step; along a diagonal the reach is sqrt(2) larger
// (<= 14 % + 1.4 steps), but only when both ends land in opposite window corners, and the rounding share
// is Round's as well. Measured at R = 10 mm, 160 steps/mm, tol 0.002 mm: the longest snapped chord spans
// 0.956 of the tolerance's span (sagitta 0.91 x tol).
inline constexpr double kOnArcSagittaShare = 0.8;

struct CamOptions {
    // Largest distance between a chord and its arc (sagitta). seed 000 Q9 gives no value; 0.002 mm is grbl's
    // $12 arc tolerance default (peers.md §1), a third of one 6.25 um microstep.
    double chord_tolerance_mm = 0.002;
    FeedRounding feed_rounding = FeedRounding::Round;
    // seed 000 Q10: whether G0 feed is corrected to the dominant axis is unclear; true treats G0 like G1
    // (coordinated straight line at the rapid path speed), false sends the rapid feed unchanged.
    bool correct_rapid_feed = true;
    ChordEnds chord_ends = ChordEnds::OnArc;
};

struct MotionSegment {                // one motion packet = one steps-file row
    int index = 0;                    // segment number, 1-based
    MotionKind motion = MotionKind::Rapid;  // packet motion byte 0..3 (chords of G2/G3 keep 2/3)
    std::int64_t steps_x = 0;         // signed; int64 so that values outside int32 are detected, not wrapped
    std::int64_t steps_y = 0;
    std::int64_t feed = 0;            // packet FeedRate: dominant-axis feed, mm/min (before the uint16 range check)
    double path_feed_mm_per_min = 0;  // programmed F (steps-file documentation column PathFeed)
    int move = -1;                    // index into Program::moves (-1 when read from a steps file)
    int line = 0;                     // G-code source line (0 when unknown)
    double dx_mm = 0;                 // steps_x / steps_per_mm: the displacement the machine really makes
    double dy_mm = 0;                 // (steps-file documentation columns DX, DY)
};

// Throws cnc::BadInput("file:line", ...) for an invalid machine, steps outside int32, or a packet feed
// outside 1..65535 after rounding. Segments with no steps on either axis are dropped.
std::vector<MotionSegment> cam(const Program& program, const MachineModel& machine, const CamOptions& opt);

// Number of chords for an arc of `radius_mm` sweeping `sweep_rad`, so that no chord is more than
// `tolerance_mm` from the arc.
std::int64_t chord_count(double radius_mm, double sweep_rad, double tolerance_mm);

// seed 000 §2.2: NUMERATOR = CLK_HZ x 60 / steps_per_mm, rounded (18,750,000 at 160 steps/mm); the FPGA's
// cycles per step are NUMERATOR / FeedRate. BadInput if it is 0 or does not fit uint32.
std::uint32_t numerator(double steps_per_mm, std::uint32_t clk_hz = 50'000'000);

}  // namespace cnc::host
