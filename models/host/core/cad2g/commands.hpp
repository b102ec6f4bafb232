// The commands the seed 003 PC program (CAD2G V42) sends to the ATmega328P firmware, and their bytes.
// The wire layout is defined once, in the firmware's protocol.h (byte order, confirm value, PORTB bits).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "avr/firmware/laser_engraver/protocol.h"
#include "host/core/cad2g/speed.hpp"
#include "host/core/cad2g/variant.hpp"
#include "host/core/gcode.hpp"

namespace cnc::host::cad2g {

enum class CommandId : std::uint8_t {
    G00 = LASER_ENGRAVER_CMD_G00,
    G01 = LASER_ENGRAVER_CMD_G01,
    G02 = LASER_ENGRAVER_CMD_G02,
    G03 = LASER_ENGRAVER_CMD_G03,
    M30 = LASER_ENGRAVER_CMD_M30,
};

inline constexpr std::uint8_t kConfirmByte = LASER_ENGRAVER_CONFIRM;
inline constexpr std::uint32_t kSeedBaud = LASER_ENGRAVER_BAUD;

// One start byte: a G00, a G01, or one chord of an arc.
struct Motion {
    int move = -1;  // index into Program::moves
    int line = 0;   // G-code line
    MotionKind kind = MotionKind::Rapid;
    int chord = -1;            // 0-based chord of its arc; -1 for G00 / G01
    std::int64_t steps_x = 0;  // signed displacement on the step grid the PC intends
    std::int64_t steps_y = 0;
    std::uint16_t count_x = 0;          // X count sent (G01 and chords: |dx|, or |dy| as a timebase when dx = 0)
    std::uint16_t count_y = 0;          // G00 only: Y count sent
    bool x_timebase = false;            // dx = 0: X's timer times |dy| steps, with X disabled (seed 003 §5.4.2 note 1)
    bool y_counted = false;             // timer1-y G01 with dx = 0: count_x holds |dy|, counted on Y's own timer
    bool wrapped = false;               // a count above 16 bits, sent modulo 65536 (atmega.long_moves = wrap)
    double path_feed_mm_per_min = 0.0;  // programmed F (G00: the rapid feed, v_max)
    double speed_x_mm_per_s = 0.0;      // asked per-axis speeds (eqs. 4.76; G00: v_max on both)
    double speed_y_mm_per_s = 0.0;
    Ocr ocr_x;               // OCR0A
    Ocr ocr_y;               // OCR2A (Variant::Timer1Y: OCR1A)
    std::uint8_t portb = 0;  // start byte
};

struct Command {
    CommandId id = CommandId::M30;
    std::vector<Motion> motions;  // G00 / G01: one; G02 / G03: the chords; M30: none
};

// PORTB start byte: DIR 1 = negative, EN 1 = disabled (seed 003 §5.2.5); HEADER = head on (PB1, or PB3 in
// the timer1-y build: protocol.h).
[[nodiscard]] std::uint8_t start_byte(std::int64_t steps_x, bool enable_x, std::int64_t steps_y, bool enable_y,
                                      bool header, Variant variant = Variant::Seed);
[[nodiscard]] bool enabled_x(std::uint8_t portb);
[[nodiscard]] bool enabled_y(std::uint8_t portb);

// The bytes of one motion after the command's ID (protocol.h): G00 7 - 1, G01 6 - 1, chord 4; the timer1-y
// build's 16-bit Y word adds one byte to each.
[[nodiscard]] std::vector<std::uint8_t> motion_bytes(CommandId id, const Motion& m, Variant variant = Variant::Seed);
// The record that ends an arc: DXL 0, every OCR byte 255, PORTB with both EN bits high and the head left as it was.
[[nodiscard]] std::vector<std::uint8_t> arc_terminator(bool header, Variant variant = Variant::Seed);
// Every byte of a command, ID first.
[[nodiscard]] std::vector<std::uint8_t> command_bytes(const Command& c, Variant variant = Variant::Seed);

}  // namespace cnc::host::cad2g
