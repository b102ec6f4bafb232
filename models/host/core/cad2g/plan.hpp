// The seed 003 PC program (CAD2G V42, §5.4) from interpreted G-code to commands: step counts on the absolute
// step grid, per-axis speeds and their truncated 8-bit OCR words, arcs as chords, DIR/EN/HEADER start bytes,
// and the order in which the bytes go out (one per confirm).
//
// Decisions where the seed is silent (the firmware's are in models/avr/firmware/laser_engraver/README.md):
// - F is the programmed path speed (the interpreter converts mm/s or mm/min); G00 runs both axes at v_max =
//   the rapid feed (machine.rapid_feed_mm_per_min), one OCR for both timers.
// - Head: on (HEADER = 1) for G01/G02/G03, off for G00, as CAD2G's pen down/up; M3/M5 are not sent.
// - Arcs: the sweep is cut into equal chords of at most atmega.arc_step_deg, and more when a chord would exceed
//   the 8-bit DXL (255 steps); the ends are on the absolute step grid and the last one is the programmed end.
//   (The seed steps alpha1 by a fixed angle while alpha1 <= alpha2, with atan: up to one step angle short of the
//   end, and wrong outside the first quadrant.) DIR comes from the sign of each chord's displacement, which is
//   Tables 5.2/5.3 for every chord that does not cross an axis. A chord with dx = 0 (X disabled) flips DIR_X
//   against the chord before it: the driver ignores it, and every chord start then changes a PORTB pin, which is
//   how the measurements find the chord boundaries without an extra pin (sim/architectures/atmega/motion_windows.hpp).
// - dx = 0 (G01 and chords): the seed's workaround, count |dy| on X's timer at Y's speed with X disabled.
// - A count above 16 bits (409.6 mm at 160 steps/mm) is split into commands that fit (LongMoves::Split, with a
//   warning) or sent modulo 65536 as the seed's registers would take it (LongMoves::Wrap, with a warning).
// - An OCR outside 0..255 is held to the range, with a warning naming the line and the speed.
// - avr.variant (variant.hpp): "rounded" rounds OCR0A, asks Y for (dy/dx) times the speed the rounded OCR0A gives,
//   and rounds OCR2A (seed 003 §5.6, interpolation 1-3; G00 rounds its one OCR). "timer1-y" does the same with
//   Y's word as OCR1A at N = 1 (16 bits, §5.6 hardware 2); its G00 sends Y its own word for the speed X's
//   rounded OCR0A gives (the seed's one OCR runs both axes at one speed), and a G01
//   with dx = 0 is counted on Y's own timer (the seed's X timebase would hold Y to X's 8-bit rate). An arc chord
//   with dx = 0 keeps the X timebase, Y in step with it: OCR1A + 1 = 1024 (OCR0A + 1), so that the chord ends are
//   still found on the pins (sim/architectures/atmega/motion_windows.hpp).
#pragma once
#include <string>
#include <vector>

#include "common/warning.hpp"
#include "host/core/cad2g/commands.hpp"
#include "host/core/cad2g/speed.hpp"
#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::host::cad2g {

enum class LongMoves { Split, Wrap };

struct PcOptions {
    TimerClock timer;  // what the PC computes X's OCR0A with (seed: 16 MHz, N = 1024), and Y's but in timer1-y
    Variant variant = Variant::Seed;  // avr.variant
    double arc_step_deg = 2.0;        // seed §5.4.3 "stepangle" (value not given): atmega.arc_step_deg
    LongMoves long_moves = LongMoves::Split;
};

struct Plan {
    std::vector<Command> commands;  // the program's moves, then M30
    std::vector<Warning> warnings;  // kinds long_move, ocr0a_range, ocr2a_range (ocr1a_range); where: the G-code line
    Variant variant = Variant::Seed;
    TimerClock timer_x;  // Timer0's clock, as the PC computed with it
    TimerClock timer_y;  // Y's: Timer2's, or Timer1's in timer1-y
};

// Throws cnc::BadInput for an invalid machine or option.
[[nodiscard]] Plan plan_program(const Program& program, const MachineModel& machine, const PcOptions& opt);

// Bytes the PC computes in one go, then writes one per confirm: a G00/G01 command, the ID with an arc's first
// chord, each further chord, an arc's terminator, M30.
struct Transfer {
    std::size_t command = 0;  // index into Plan::commands
    int motion = -1;          // index into the command's motions; -1 for a terminator or M30
    std::vector<std::uint8_t> bytes;
};
[[nodiscard]] std::vector<Transfer> transfers(const Plan& plan);

// The motions as motion segments (run/moves.hpp turns them into the metrics' move list).
[[nodiscard]] std::vector<MotionSegment> motion_segments(const Plan& plan, const MachineModel& machine);

}  // namespace cnc::host::cad2g
