#include "host/core/cad2g/commands.hpp"

namespace cnc::host::cad2g {

namespace {

std::uint8_t bit(int n) {
    return static_cast<std::uint8_t>(1U << n);
}
std::uint8_t low(std::uint16_t v) {
    return static_cast<std::uint8_t>(v & 0xFFU);
}
std::uint8_t high(std::uint16_t v) {
    return static_cast<std::uint8_t>(v >> 8);
}

// Y's speed word: OCR2A, or OCR1A low byte first (protocol.h).
void append_y_word(std::vector<std::uint8_t>& b, std::uint16_t ocr_y, Variant variant) {
    b.push_back(low(ocr_y));
    if (variant == Variant::Timer1Y) b.push_back(high(ocr_y));
}

}  // namespace

std::uint8_t start_byte(std::int64_t steps_x, bool enable_x, std::int64_t steps_y, bool enable_y, bool header,
                        Variant variant) {
    std::uint8_t b = LASER_ENGRAVER_PORTB_INPUTS;
    if (steps_x < 0) b |= bit(LASER_ENGRAVER_PB_DIR_X);
    if (!enable_x) b |= bit(LASER_ENGRAVER_PB_EN_X);
    if (steps_y < 0) b |= bit(LASER_ENGRAVER_PB_DIR_Y);
    if (!enable_y) b |= bit(LASER_ENGRAVER_PB_EN_Y);
    if (header) b |= bit(variant == Variant::Timer1Y ? LASER_ENGRAVER_T1Y_PB_HEADER : LASER_ENGRAVER_PB_HEADER);
    return b;
}

bool enabled_x(std::uint8_t portb) {
    return (portb & bit(LASER_ENGRAVER_PB_EN_X)) == 0;
}
bool enabled_y(std::uint8_t portb) {
    return (portb & bit(LASER_ENGRAVER_PB_EN_Y)) == 0;
}

std::vector<std::uint8_t> motion_bytes(CommandId id, const Motion& m, Variant variant) {
    std::vector<std::uint8_t> b;
    switch (id) {
        case CommandId::G00:
            b = {low(m.count_x), high(m.count_x), low(m.count_y), high(m.count_y), low(m.ocr_x.value)};
            // The seed's G00 sends one OCR for both timers; Timer1 needs its own word.
            if (variant == Variant::Timer1Y) append_y_word(b, m.ocr_y.value, variant);
            break;
        case CommandId::G01:
            b = {low(m.count_x), high(m.count_x), low(m.ocr_x.value)};
            append_y_word(b, m.ocr_y.value, variant);
            break;
        case CommandId::G02:
        case CommandId::G03:
            b = {low(m.count_x), low(m.ocr_x.value)};
            append_y_word(b, m.ocr_y.value, variant);
            break;
        case CommandId::M30:
            return b;
    }
    b.push_back(m.portb);
    return b;
}

std::vector<std::uint8_t> arc_terminator(bool header, Variant variant) {
    std::vector<std::uint8_t> b{0x00, 0xFF};
    append_y_word(b, 0xFFFF, variant);
    b.push_back(start_byte(0, false, 0, false, header, variant));
    return b;
}

std::vector<std::uint8_t> command_bytes(const Command& c, Variant variant) {
    std::vector<std::uint8_t> bytes{static_cast<std::uint8_t>(c.id)};
    for (const Motion& m : c.motions) {
        const std::vector<std::uint8_t> b = motion_bytes(c.id, m, variant);
        bytes.insert(bytes.end(), b.begin(), b.end());
    }
    if (c.id == CommandId::G02 || c.id == CommandId::G03) {
        const std::vector<std::uint8_t> t = arc_terminator(true, variant);
        bytes.insert(bytes.end(), t.begin(), t.end());
    }
    return bytes;
}

}  // namespace cnc::host::cad2g
