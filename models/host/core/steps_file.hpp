// The seed 000 "steps file" (§3.4.3, App. A.2): the CSV that GCODESTEPS.LSP writes and send_steps.py reads, one row
// per motion packet.
//
// Columns. The sender (A.2) reads 0 = segment number, 2 = motion code, 5 = X steps, 6 = Y steps, 8 = feed; the
// thesis prints no header and leaves 1, 3, 4 and 7 undocumented. We name them after T3.5/T3.7, whose
// example row has the columns G-code, DX, DY, StepsX, StepsY, FeedRate and "PathFeed stays in the CSV":
//   0 Segment  1 GcodeLine  2 Motion  3 DX_mm  4 DY_mm  5 StepsX  6 StepsY  7 PathFeed  8 FeedRate
// GcodeLine is the source line number (0 = unknown) rather than the G-code text, which may contain commas.
// DX_mm/DY_mm are the step-quantised displacements and PathFeed the programmed F, both documentation only.
#pragma once
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "host/core/cam.hpp"

namespace cnc::host {

inline constexpr const char* kStepsFileHeader = "Segment,GcodeLine,Motion,DX_mm,DY_mm,StepsX,StepsY,PathFeed,FeedRate";

// Writes the header and one row per segment; numbers are written exactly (shortest round-trip form).
void write_steps_file(std::ostream& out, const std::vector<MotionSegment>& segments);
void save_steps_file(const std::string& path, const std::vector<MotionSegment>& segments);  // BadInput if unwritable

// Reads a steps file strictly: unlike send_steps.py, which warns, clamps and skips, any bad row is an error
// cnc::BadInput("file:line", ...). Line 1 is the header and is skipped whatever it holds (as the sender does);
// empty lines are skipped; columns after the ninth are ignored. Every numeric column must parse; Segment,
// GcodeLine, Motion, StepsX and StepsY must be integers; Motion 0..3; steps int32; FeedRate (a number, rounded
// half-to-even like the sender's Python round()) 0..65535. The result has move = -1.
std::vector<MotionSegment> read_steps_file(std::istream& in, const std::string& filename);
std::vector<MotionSegment> load_steps_file(const std::string& path);  // BadInput if unreadable

}  // namespace cnc::host
