#include "lathe/core/hd44780.hpp"

namespace cnc::lathe {

namespace {

constexpr int kLineChars = 40;  // DDRAM characters per line in 2-line mode (datasheet "Display Data RAM")
constexpr int kLine2Address = 0x40;
constexpr std::uint8_t kSpace = 0x20;

// Character generator ROM A00 (datasheet Table 4): ASCII from 0x20 to 0x7D except 0x5C (a yen sign).
char glyph(std::uint8_t code) {
    return code >= 0x20 && code <= 0x7D && code != 0x5C ? static_cast<char>(code) : '?';
}

}  // namespace

Hd44780::Hd44780() {
    m_ddram.fill(kSpace);
    m_shown = lines();
}

void Hd44780::pins(bool rs, bool rw, bool e, std::uint8_t db7_db4) {
    const bool falling = m_e && !e;
    m_e = e;
    if (!falling) return;
    const auto nibble = static_cast<std::uint8_t>(db7_db4 & 0x0F);
    if (m_eight_bit) {  // DB3..DB0 are not wired in the 4-bit hookup: they read 0
        transfer(rs, rw, static_cast<std::uint8_t>(nibble << 4));
        return;
    }
    // 4-bit mode: every transfer, reads included, takes two E pulses, high nibble first.
    if (!m_second_nibble) {
        m_high_nibble = nibble;
        m_second_nibble = true;
        return;
    }
    m_second_nibble = false;
    transfer(rs, rw, static_cast<std::uint8_t>(m_high_nibble << 4 | nibble));
}

void Hd44780::transfer(bool rs, bool rw, std::uint8_t db7_db0) {
    if (rw) return;  // busy flag / data reads change nothing visible
    if (rs) {
        write_data(db7_db0);
    } else {
        instruction(db7_db0);
    }
    touched();
}

// Datasheet Table 6, the highest set bit selects the instruction.
void Hd44780::instruction(std::uint8_t code) {
    if ((code & 0x80) != 0) {  // set DDRAM address
        m_address_cgram = false;
        m_address = code & 0x7F;
    } else if ((code & 0x40) != 0) {  // set CGRAM address
        m_address_cgram = true;
        m_address = code & 0x3F;
    } else if ((code & 0x20) != 0) {  // function set: DL (bit 4), N (bit 3)
        m_eight_bit = (code & 0x10) != 0;
        m_two_lines = (code & 0x08) != 0;
    } else if ((code & 0x10) != 0) {  // cursor or display shift: S/C (bit 3), R/L (bit 2)
        const bool right = (code & 0x04) != 0;
        if ((code & 0x08) != 0) {
            m_display_shift += right ? 1 : -1;
        } else {
            step_address(right);
        }
    } else if ((code & 0x08) != 0) {  // display on/off control: D (bit 2)
        m_display_on = (code & 0x04) != 0;
    } else if ((code & 0x04) != 0) {  // entry mode set: I/D (bit 1), S (bit 0)
        m_increment = (code & 0x02) != 0;
        m_shift_on_write = (code & 0x01) != 0;
    } else if ((code & 0x02) != 0) {  // return home
        m_address_cgram = false;
        m_address = 0;
        m_display_shift = 0;
    } else if ((code & 0x01) != 0) {  // clear display: spaces, address 0, I/D = 1, no shift
        m_ddram.fill(kSpace);
        m_address_cgram = false;
        m_address = 0;
        m_display_shift = 0;
        m_increment = true;
    }
}

void Hd44780::write_data(std::uint8_t code) {
    if (m_address_cgram) {  // a glyph row: no character is displayed from it here
        m_address = (m_address + (m_increment ? 1 : -1)) & 0x3F;
        return;
    }
    m_ddram[static_cast<std::size_t>(ddram_index(m_address))] = code;
    step_address(m_increment);
    if (m_shift_on_write) m_display_shift += m_increment ? -1 : 1;  // the display moves with the cursor
}

// 2-line mode: 0x27 is followed by 0x40 and 0x67 by 0x00; 1-line mode: 0x4F by 0x00 (datasheet "Display Data RAM").
void Hd44780::step_address(bool increment) {
    if (m_address_cgram) {
        m_address = (m_address + (increment ? 1 : -1)) & 0x3F;
        return;
    }
    if (!m_two_lines) {
        m_address = (m_address + (increment ? 1 : -1) + 80) % 80;
        return;
    }
    const int line = m_address >= kLine2Address ? 1 : 0;
    const int pos = (m_address & 0x3F) % kLineChars;
    const int linear = (line * kLineChars + pos + (increment ? 1 : -1) + 2 * kLineChars) % (2 * kLineChars);
    m_address = linear / kLineChars * kLine2Address + linear % kLineChars;
}

int Hd44780::ddram_index(int address) const {
    if (!m_two_lines) return address % 80;
    return (address >= kLine2Address ? kLineChars : 0) + (address & 0x3F) % kLineChars;
}

LcdLines Hd44780::lines() const {
    LcdLines out;
    for (int l = 0; l < kLcdLines; ++l) {
        std::string& text = out[static_cast<std::size_t>(l)];
        text.assign(kLcdColumns, ' ');
        if (!m_display_on || (l == 1 && !m_two_lines)) continue;
        const int chars = m_two_lines ? kLineChars : 2 * kLineChars;
        for (int c = 0; c < kLcdColumns; ++c) {
            const int pos = ((c - m_display_shift) % chars + chars) % chars;
            text[static_cast<std::size_t>(c)] = glyph(m_ddram[static_cast<std::size_t>(l * kLineChars + pos)]);
        }
    }
    return out;
}

void Hd44780::touched() {
    LcdLines now = lines();
    if (now == m_shown) return;
    m_shown = std::move(now);
    ++m_changes;
}

}  // namespace cnc::lathe
