// CAM of seed 000 §3.4 (GCODE2STEPS): programmed moves -> motion segments (one motion packet and one
// steps-file row each): arcs as chords, mm -> signed steps, and the dominant-axis feed ("NUMERATOR concept").
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::host {

// How the host makes the packet's integer FeedRate: seed 000 §3.4.7 sends axisFeed 894.43 as 894 but does not say
// whether it rounds or truncates.
enum class FeedRounding { Round, Truncate };

// Where the interior chord ends of an arc go on the step grid. The arc's programmed end point is always rounded
// per axis, so that the next move starts where the program says.
// - Round: seed 000 §3.4.4 literally ("each intermediate point goes through the same mm->steps rounding"):
//   llround per axis of each vertex of the inscribed polygon, up to 0.71 step off the circle.
// - OnArc: the grid point nearest the circle among those within a few steps of the vertex that keep the chords
//   in order and non-empty (rule and margin in cam.cpp).
// Why OnArc is the default: the FPGA's reference-word step generator (seed 000 §5.2.4) steps the subordinate
// axis at the start of its period, a staircase that adds up to one step to the path; with the chord ends on the
// circle the path can stay within the chord tolerance plus one step, while Round adds the end's own 0.71 step.
// Measured with the fpga-uart model, radius 10 mm, 160 steps/mm, tolerance 0.002 mm (limit 8.25 um): centre
// on the grid 7.8 um (Round 9.6 um; OnArc's ends lie within 0.18 step of that circle). Limit: where the tangent
// runs along an axis and the circle misses the grid points, none within reach is much nearer than the rounded
// one (up to half a step), so off-grid centres still reach 8.1-9.7 um (Round 10.4-10.6 um).
enum class ChordEnds { OnArc, Round };

// ChordEnds::OnArc counts chords for this share of the chord tolerance, so that snapping the ends may lengthen
// a chord by 1/sqrt(0.8) - 1 = 11.8 % before its sagitta reaches the tolerance (derivation in cam.cpp).
inline constexpr double kOnArcSagittaShare = 0.8;

struct CamOptions {
    // Largest distance between a chord and its arc (sagitta). Seed 000 gives no value; 0.002 mm is grbl's
    // $12 arc tolerance default (gnea/grbl v1.1h defaults.h), a third of one 6.25 um microstep.
    double chord_tolerance_mm = 0.002;
    FeedRounding feed_rounding = FeedRounding::Round;
    // Seed 000 does not say whether G0's feed gets §3.4.5's dominant-axis correction; true treats G0 like G1
    // (coordinated straight line at the rapid path speed), false sends the rapid feed unchanged.
    bool correct_rapid_feed = true;
    ChordEnds chord_ends = ChordEnds::OnArc;  // see ChordEnds
};

struct MotionSegment {                      // one motion packet = one steps-file row
    int index = 0;                          // segment number, 1-based
    MotionKind motion = MotionKind::Rapid;  // packet motion byte 0..3 (chords of G2/G3 keep 2/3)
    std::int64_t steps_x = 0;               // signed; int64 so that values outside int32 are detected, not wrapped
    std::int64_t steps_y = 0;
    std::int64_t feed = 0;            // packet FeedRate: dominant-axis feed, mm/min (before the uint16 range check)
    double path_feed_mm_per_min = 0;  // programmed F (steps-file documentation column PathFeed)
    int move = -1;                    // index into Program::moves (-1 when read from a steps file)
    int line = 0;                     // G-code source line (0 when unknown)
    double dx_mm = 0;                 // steps_x / steps_per_mm: the displacement the machine really makes
    double dy_mm = 0;                 // (steps-file documentation columns DX, DY)
};

// The CAM one programmed move at a time, as a streamed job's moves are read; cam() is the whole program's case.
// Throws as cam() does. `machine` must outlive it.
class CamStream {
public:
    CamStream(std::string filename, const MachineModel& machine, const CamOptions& opt);
    // Appends the segments of programmed move number `m` (0-based; moves in program order).
    void add(const ProgrammedMove& move, std::size_t m, std::vector<MotionSegment>& out);
    [[nodiscard]] std::size_t segments() const { return m_segments; }  // made so far

private:
    std::string m_file;
    const MachineModel& m_machine;
    CamOptions m_opt;
    bool m_started = false;
    std::int64_t m_at_x = 0, m_at_y = 0;  // step position after the segments made
    std::size_t m_segments = 0;
};

// Throws cnc::BadInput("file:line", ...) for an invalid machine, steps outside int32, or a packet feed
// outside 1..65535 after rounding. Segments with no steps on either axis are dropped.
std::vector<MotionSegment> cam(const Program& program, const MachineModel& machine, const CamOptions& opt);

// Number of chords for an arc of `radius_mm` sweeping `sweep_rad`, so that no chord is more than
// `tolerance_mm` from the arc.
std::int64_t chord_count(double radius_mm, double sweep_rad, double tolerance_mm);

// seed 000 §3.4.5: NUMERATOR = CLK_HZ x 60 / steps_per_mm, rounded (18,750,000 at 160 steps/mm); the FPGA's
// cycles per step are NUMERATOR / FeedRate. BadInput if it is 0 or does not fit uint32.
std::uint32_t numerator(double steps_per_mm, std::uint32_t clk_hz = 50'000'000);

}  // namespace cnc::host
