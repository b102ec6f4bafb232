// G-code interpreter for the words the seed 000 CAM emits (T2.1) plus G91, G20, G92 and the R arc form:
// turns a program into moves in machine millimetres. Anything else is rejected with the file and line.
#pragma once
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace cnc::host {

// Values equal the seed 000 motion byte (§4.2): 0 rapid (laser off), 1..3 cutting (laser on).
enum class MotionKind : std::uint8_t { Rapid = 0, Linear = 1, ArcCW = 2, ArcCCW = 3 };

// Unit of the F word: seed 000 uses mm/min (G94); seed 003's PC program takes mm/s.
enum class FeedUnit { MmPerMinute, MmPerSecond };

struct ProgrammedMove {
    MotionKind kind;
    // Machine mm. For an arc, `end` is the programmed end point exactly: it may lie up to the 0.01 mm arc
    // tolerance off the circle through the start, and the CAM's last chord goes there (as grbl's arcs do).
    geom::Segment path;
    double feed_mm_per_min;  // programmed F (path speed); rapids carry InterpreterOptions::rapid_feed_mm_per_min
    bool laser_on;           // M3 in force (programmed state; the FPGA switches the laser by motion code)
    int line;                // 1-based source line
};

struct InterpreterOptions {
    FeedUnit feed_unit = FeedUnit::MmPerMinute;
    double rapid_feed_mm_per_min = 1200.0;  // seed 000 §7.3 test log: G0 packets carry F=1200
    geom::Vec2 start_mm{};                  // machine position when the program starts
};

struct Program {
    std::string filename;
    std::vector<ProgrammedMove> moves;
};

// Supported: G0 G1 G2 G3 (I/J centre offsets from the start, or R: R>0 the arc <= 180 deg, R<0 the longer one),
// G17 G94 (no-ops), G20/G21, G90/G91, G92, F, M3/M5 (S ignored), M2/M30 (rest of the file ignored), N,
// comments. Zero-length moves are dropped. Throws cnc::BadInput("file:line", ...) on anything else.
Program interpret(std::istream& in, const std::string& filename, const InterpreterOptions& opt);
// BadInput if the file cannot be read.
Program interpret_file(const std::string& path, const InterpreterOptions& opt);

}  // namespace cnc::host
