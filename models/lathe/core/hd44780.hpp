// The Hitachi HD44780U LCD controller of seed 002's 16x2 display (§2.3, App. A.1: 4-bit interface, DB4..DB7 on
// PA0..PA3, RS = PA4, R/W = PA5, E = PA6; line 2 at DDRAM 0x40), as the controller sees its pins: data and
// instructions are latched on E's falling edge (HD44780U datasheet, Figure 25 write timing). It decodes the
// instruction set of datasheet Table 6 into the display's visible contents. Not modelled: the busy flag and
// execution times (the rig's controller is always ready: the firmware polls the flag, so only its waits would
// change), CGRAM glyphs (their codes 0x00..0x0F show as '?'), and the cursor.
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace cnc::lathe {

inline constexpr int kLcdColumns = 16;  // 16x2 module (seed 002 §2.3)
inline constexpr int kLcdLines = 2;

using LcdLines = std::array<std::string, kLcdLines>;

class Hd44780 {
public:
    Hd44780();

    // The pins at one instant (DB7..DB4 as bits 3..0 of db7_db4); an E falling edge transfers.
    void pins(bool rs, bool rw, bool e, std::uint8_t db7_db4);

    // The visible characters of each line (kLcdColumns each; blank while the display is off or a line unused).
    [[nodiscard]] LcdLines lines() const;
    // Counts changes of the visible contents (a write that changes nothing visible does not count).
    [[nodiscard]] std::uint64_t changes() const { return m_changes; }
    [[nodiscard]] bool four_bit() const { return !m_eight_bit; }

private:
    void transfer(bool rs, bool rw, std::uint8_t db7_db0);
    void instruction(std::uint8_t code);
    void write_data(std::uint8_t code);
    void step_address(bool increment);
    [[nodiscard]] int ddram_index(int address) const;
    void touched();

    bool m_e = false;
    bool m_eight_bit = true;   // after power-on reset: 8-bit interface, 1 line (datasheet "Initializing by
    bool m_two_lines = false;  // Internal Reset Circuit")
    bool m_display_on = false;
    bool m_increment = true;
    bool m_shift_on_write = false;
    bool m_second_nibble = false;  // 4-bit mode: the high nibble has been transferred
    std::uint8_t m_high_nibble = 0;
    bool m_address_cgram = false;
    int m_address = 0;        // the address counter, DDRAM (0x00..0x27, 0x40..0x67 in 2-line mode) or CGRAM
    int m_display_shift = 0;  // columns the display has shifted right
    std::array<std::uint8_t, 80> m_ddram{};
    LcdLines m_shown;
    std::uint64_t m_changes = 0;
};

}  // namespace cnc::lathe
