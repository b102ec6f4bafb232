// CAM of seed 000 §3.4-3.5 (GCODE2STEPS): programmed moves -> motion segments (one motion packet and one
// steps-file row each): arcs as chords, mm -> signed steps, and the dominant-axis feed ("NUMERATOR concept").
#pragma once
#include <cstdint>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::host {

enum class FeedRounding { Round, Truncate };  // seed 000 Q6: the host's rounding of axisFeed is unstated

struct CamOptions {
    // Largest distance between a chord and its arc (sagitta). seed 000 Q9 gives no value; 0.002 mm is grbl's
    // $12 arc tolerance default (peers.md §1), a third of one 6.25 um microstep.
    double chord_tolerance_mm = 0.002;
    FeedRounding feed_rounding = FeedRounding::Round;
    // seed 000 Q10: whether G0 feed is corrected to the dominant axis is unclear; true treats G0 like G1
    // (coordinated straight line at the rapid path speed), false sends the rapid feed unchanged.
    bool correct_rapid_feed = true;
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
