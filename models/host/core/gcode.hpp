// G-code interpreter for what RS274/NGC (LinuxCNC), grbl and laser tools emit: turns a program into the moves
// of the modelled XY machine (machine millimetres), the host waits between them (dwells, operator pauses, moves
// of axes the machine has no STEP pins for) and the list of words this machine ignores. The table of every word
// and its effect is docs/gcode.md; each decision is at the code that makes it (gcode.cpp, gcode_words.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace cnc::host {

class ToolTable;

// Values equal the seed 000 motion byte (§4.7): 0 rapid (laser off), 1..3 cutting (laser on).
enum class MotionKind : std::uint8_t { Rapid = 0, Linear = 1, ArcCW = 2, ArcCCW = 3 };

// Unit of the F word: seed 000 uses mm/min (G94); seed 003's PC program takes mm/s.
enum class FeedUnit { MmPerMinute, MmPerSecond };

// lenient: run what the machine can do and list what it ignores; strict: every word the machine does not
// execute is an error. Either way every unsupported word of the file is reported at once.
enum class GcodePolicy { Lenient, Strict };

// M5 off, M3 constant power, M4 grbl's dynamic power (scaled with the speed).
enum class LaserMode { Off, Constant, Dynamic };

// G61 exact path, G61.1 exact stop, G64 blending (P: the path tolerance), as LinuxCNC's G-code reference names them.
enum class PathMode { ExactStop, ExactPath, Blend };

struct PathControl {
    PathMode mode = PathMode::Blend;
    std::optional<double> tolerance_mm;  // G64 P, machine mm; none: the planner's own tolerance
};

struct ProgrammedMove {
    MotionKind kind;
    // Machine mm. For an arc, `end` is the programmed end point exactly: it may lie up to the 0.01 mm arc
    // tolerance off the circle through the start, and the CAM's last chord goes there (as grbl's arcs do).
    geom::Segment path;
    // XY path speed, mm/min: the programmed F (rapids: InterpreterOptions::rapid_feed_mm_per_min), less the
    // share of a simultaneous Z move, so that the XY path takes the time the whole move takes at F.
    double feed_mm_per_min;
    bool laser_on;  // M3 or M4 in force (programmed state; the FPGA switches the laser by motion code)
    int line;       // 1-based source line
    LaserMode laser_mode = LaserMode::Off;
    std::optional<double> power_s;            // S in force (none: never programmed)
    std::optional<PathControl> path_control;  // G61/G61.1/G64 in force (none: the planner's default)
    // Machine Z, mm (no XY architecture has Z STEP pins): the controlled point's, so with a tool length offset
    // (G43) the programmed Z plus the offset, as LinuxCNC's motion moves it; the tool tip is at the programmed Z.
    double z_start_mm = 0.0;
    double z_end_mm = 0.0;
    // The job's intent for the laser on this move: M3/M4 with S > 0 (or no S programmed) on a cutting move.
    [[nodiscard]] bool laser_intended() const {
        return kind != MotionKind::Rapid && laser_mode != LaserMode::Off && (!power_s || *power_s > 0.0);
    }
};

// Time the host spends between two moves with the XY axes at rest.
enum class WaitCause { Dwell, OperatorPause, OtherAxes };

struct HostWait {
    std::size_t before_move;  // index into Program::moves; moves.size(): after the last move
    double seconds;
    WaitCause cause;
    int line;
};

// A word the machine accepts and does nothing with, with every line it stood on.
struct IgnoredWord {
    std::string word;    // "T1", "M6", "G40", "/" (block delete)
    std::string reason;  // why it has no effect here
    std::vector<int> lines;
};

struct InterpreterOptions {
    FeedUnit feed_unit = FeedUnit::MmPerMinute;
    double rapid_feed_mm_per_min = 1200.0;  // seed 000 §6.3.1 test log: G0 packets carry F=1200
    geom::Vec2 start_mm{};                  // machine position when the program starts
    GcodePolicy policy = GcodePolicy::Lenient;
    // scenario.feed_mm_per_min: every F word read as this feed (units per minute mode only); none: the job's F.
    std::optional<double> feed_mm_per_min;
    double operator_pause_s = 5.0;  // M0/M1/M60: the time an operator takes to press cycle start
    // machine.z.max_velocity_mm_per_s: a move is slowed so that its Z part stays within it.
    double z_max_feed_mm_per_min = std::numeric_limits<double>::infinity();
    // scenario.tool_table: with it T, M6, M61, G43/G43.1/G43.2/G49 (H) and G40/G41/G42/G41.1/G42.1 (D) are
    // executed as LinuxCNC does; without it they are ignored words (docs/gcode.md).
    std::shared_ptr<const ToolTable> tool_table;
};

struct Program {
    std::string filename;
    std::vector<ProgrammedMove> moves;
    std::vector<HostWait> waits;       // in program order
    std::vector<IgnoredWord> ignored;  // in order of first appearance
    double z_travel_mm = 0.0;          // Z travel, which the XY machines time as host waits
    int lines = 0;                     // source lines read (up to the program end)
    std::size_t move_count = 0;        // moves made: `moves` holds them unless the program was streamed

    // Total seconds of the waits of one cause.
    [[nodiscard]] double wait_s(WaitCause cause) const;
    // Seconds of every wait with before_move in [first, last).
    [[nodiscard]] double wait_s_between(std::size_t first, std::size_t last) const;
};

const char* to_string(WaitCause cause);

// The program read a line at a time, each move handed over as it is made, so that a long job need not be held
// whole: with keep_moves = false, Program::moves stays empty and program() is the rest (lines, waits, ignored
// words, Z travel, move_count). The problems of the file (interpret()'s BadInput) are thrown once its end is
// read, after the moves before it have been handed over: a caller that acts on moves reads the file twice.
class GcodeStream {
public:
    GcodeStream(std::istream& in, const std::string& filename, const InterpreterOptions& opt, bool keep_moves);
    // BadInput if the file cannot be opened.
    GcodeStream(const std::string& path, const InterpreterOptions& opt, bool keep_moves);
    ~GcodeStream();
    GcodeStream(const GcodeStream&) = delete;
    GcodeStream& operator=(const GcodeStream&) = delete;

    // The next move; none once the program has ended (M2/M30, the closing '%' or the end of the file).
    [[nodiscard]] std::optional<ProgrammedMove> next();
    // What is known of the program so far; all of it once next() has returned none.
    [[nodiscard]] const Program& program() const;
    [[nodiscard]] Program take();

private:
    class LineReader;
    struct State;
    std::unique_ptr<std::istream> m_file;
    std::unique_ptr<State> m_state;
};

// Throws cnc::BadInput naming the file and line(s): one message for every problem of the file (unsupported
// words with all their lines, malformed or impossible blocks), nothing executed.
Program interpret(std::istream& in, const std::string& filename, const InterpreterOptions& opt);
// BadInput if the file cannot be read.
Program interpret_file(const std::string& path, const InterpreterOptions& opt);

}  // namespace cnc::host
