#include "architectures/atmega/atmega_settings.hpp"

namespace cnc::sim {

namespace {

host::cad2g::Variant read_variant(KeyReader& r) {
    using host::cad2g::Variant;
    const std::string v = r.get_choice(
        "avr.variant", "seed", {"seed", "rounded", "timer1-y"},
        "atmega: seed 003 §5.6's proposals: seed (OCRs truncated), rounded (OCR0A rounded, v_y = (dy/dx) v_x of it, "
        "OCR2A rounded: the PC program only), timer1-y (rounded, Y on Timer1 at N = 1 with a 16-bit OCR1A on PB1, "
        "the head on PB3: its own firmware build, protocol and default avr.pins)");
    return v == "seed" ? Variant::Seed : v == "rounded" ? Variant::Rounded : Variant::Timer1Y;
}

}  // namespace

void read_atmega_settings(KeyReader& r, AtmegaSettings& s, const std::filesystem::path& base) {
    read_serial_host_settings(r, s.serial);
    read_avr_board_settings(r, s.board, base);
    s.pc.variant = read_variant(r);
    s.g01_timer2_prescaler = static_cast<int>(
        r.get_int("atmega.g01_timer2_prescaler", s.g01_timer2_prescaler, 256, 1024,
                  "atmega: Timer2 prescaler of the built firmware's G01: 1024 (what the PC computes with), or 256 "
                  "(App. A3's TCCR2B = 0b110 as listed: Y runs 4x fast)"));
    if (s.g01_timer2_prescaler != 1024 && s.g01_timer2_prescaler != 256) {
        r.fail("atmega.g01_timer2_prescaler", std::to_string(s.g01_timer2_prescaler) + " is not 1024 or 256");
    }
    if (s.g01_timer2_prescaler == 256 && s.pc.variant == host::cad2g::Variant::Timer1Y) {
        r.fail("atmega.g01_timer2_prescaler",
               "256 picks the seed firmware's G01 on Timer2; avr.variant = \"timer1-y\" "
               "runs Y on Timer1");
    }
    s.pc.arc_step_deg = r.get_float("atmega.arc_step_deg", s.pc.arc_step_deg, 0.01, 90.0,
                                    "atmega: largest angle of an arc chord, degrees (seed 003 §5.4.3 stepangle, "
                                    "value not given); chords are cut shorter when DXL would exceed 255 steps");
    s.pc.long_moves = r.get_choice("atmega.long_moves", "split", {"split", "wrap"},
                                   "atmega: a count above 16 bits (409.6 mm at 1/32): split into commands, or sent "
                                   "modulo 65536 as the seed's registers take it (a warning either way)") == "split"
                          ? host::cad2g::LongMoves::Split
                          : host::cad2g::LongMoves::Wrap;
    s.link_baud_set = r.has("link.baud");
    // Seed 003's firmware is the ATmega328P's by its protocol: the PC's start byte is an image of the 328P board's
    // PORTB with STEP_Y on OC2A (PB3), STEP_X is OC0A (PD6), and GTCCR.TSM starts both timers together, which the
    // ATmega16 does not have (its SFIOR resets the prescalers but cannot hold them).
    if (s.board.mcu != "atmega328p" && s.board.firmware.empty()) {
        r.fail("avr.mcu", "\"" + s.board.mcu +
                              "\" with seed 003's firmware, which this build makes for the ATmega328P only (its "
                              "STEP pins are the 328P's OC0A and OC2A, its start byte a PORTB image of the 328P "
                              "board, its timers started together by GTCCR.TSM): give your own firmware on seed "
                              "003's protocol built for the " +
                              s.board.mcu + " with avr.firmware, or leave avr.mcu = \"atmega328p\"");
    }
}

}  // namespace cnc::sim
