// The HD44780U decoder against the datasheet's own sequences: the 4-bit initialisation of Table 12 ("4-Bit
// Operation, 8-Digit x 1-Line Display Example with Internal Reset") and the instruction semantics of Table 6, fed
// as the pin levels a controller drives (data set up, E pulsed high and low).
#include <gtest/gtest.h>

#include <string>

#include "lathe/core/hd44780.hpp"

namespace {

using cnc::lathe::Hd44780;

// One E pulse carrying DB7..DB4 = nibble.
void pulse(Hd44780& lcd, bool rs, bool rw, int nibble) {
    const auto n = static_cast<std::uint8_t>(nibble);
    lcd.pins(rs, rw, false, n);
    lcd.pins(rs, rw, true, n);
    lcd.pins(rs, rw, false, n);
}

// A byte in 4-bit mode: high nibble, then low nibble (datasheet Figure 9).
void byte4(Hd44780& lcd, bool rs, int v) {
    pulse(lcd, rs, false, v >> 4);
    pulse(lcd, rs, false, v & 0x0F);
}

void text4(Hd44780& lcd, const std::string& s) {
    for (const char c : s) byte4(lcd, true, static_cast<unsigned char>(c));
}

std::string pad(const std::string& s) {
    return s + std::string(16 - s.size(), ' ');
}

// Table 12, steps 2 to 6: function set 0010 (one 8-bit transfer: 4-bit interface), function set 0010 0000
// (4-bit, 1 line), display on/off 0000 1110 (display on, cursor on), entry mode 0000 0110 (increment, no shift),
// then "HITACHI" as data (RS = 1), H = 0100 1000 first.
void table12_init(Hd44780& lcd) {
    pulse(lcd, false, false, 0x2);
    byte4(lcd, false, 0x20);
    byte4(lcd, false, 0x0E);
    byte4(lcd, false, 0x06);
}

TEST(Hd44780, Table12FourBitInitAndWrite) {
    Hd44780 lcd;
    EXPECT_FALSE(lcd.four_bit());  // internal reset: 8-bit interface
    EXPECT_EQ(lcd.lines()[0], pad(""));
    table12_init(lcd);
    EXPECT_TRUE(lcd.four_bit());
    EXPECT_EQ(lcd.lines()[0], pad(""));  // display on, still clear
    text4(lcd, "HITACHI");
    EXPECT_EQ(lcd.lines()[0], pad("HITACHI"));
    EXPECT_EQ(lcd.lines()[1], pad(""));  // 1-line mode: the second line is not driven
}

// E rising alone latches nothing; only the fall does (Figure 25: data held across E's falling edge).
TEST(Hd44780, LatchesOnEFallingEdge) {
    Hd44780 lcd;
    table12_init(lcd);
    lcd.pins(true, false, false, 0x4);
    lcd.pins(true, false, true, 0x4);  // high nibble of 'H' presented, E high
    lcd.pins(true, false, true, 0x5);  // data changes while E is high: the value at the fall counts
    lcd.pins(true, false, false, 0x4);
    pulse(lcd, true, false, 0x8);
    EXPECT_EQ(lcd.lines()[0], pad("H"));
}

// A busy-flag read in 4-bit mode takes two E pulses too (the high nibble holds BF): the nibble pairing of the
// writes after it is unchanged.
TEST(Hd44780, BusyReadKeepsNibblePairing) {
    Hd44780 lcd;
    table12_init(lcd);
    text4(lcd, "HI");
    pulse(lcd, false, true, 0x0);
    pulse(lcd, false, true, 0x0);
    text4(lcd, "T");
    EXPECT_EQ(lcd.lines()[0], pad("HIT"));
}

// Table 6: entry mode with S = 1 shifts the display left at each write (cursor and display move together); clear
// display puts spaces everywhere, the address to 0 and I/D back to increment; return home undoes a shift.
TEST(Hd44780, EntryShiftClearAndHome) {
    Hd44780 lcd;
    table12_init(lcd);
    text4(lcd, "HITACHI");
    byte4(lcd, false, 0x07);  // entry mode: increment, shift
    text4(lcd, " M");         // two writes: the display moves two columns left
    EXPECT_EQ(lcd.lines()[0], pad("TACHI M"));
    byte4(lcd, false, 0x02);  // return home: shift 0
    EXPECT_EQ(lcd.lines()[0], pad("HITACHI M"));
    byte4(lcd, false, 0x1C);  // display shift right
    EXPECT_EQ(lcd.lines()[0], pad(" HITACHI M"));
    byte4(lcd, false, 0x01);  // clear
    EXPECT_EQ(lcd.lines()[0], pad(""));
    text4(lcd, "AB");  // clear left I/D = 1 and the shift bit as set: each write still shifts
    byte4(lcd, false, 0x06);
    byte4(lcd, false, 0x02);
    EXPECT_EQ(lcd.lines()[0], pad("AB"));
}

// Seed 002's 16x2 set-up (the firmware's lcd_init: 0x28 = 4-bit, 2 lines): line 2 starts at DDRAM 0x40 (set DDRAM
// address 0xC0), and the address runs on from 0x27 (the 40th character of line 1) to 0x40.
TEST(Hd44780, TwoLinesAtDdram40) {
    Hd44780 lcd;
    pulse(lcd, false, false, 0x3);  // the firmware's reset-by-instruction: 0011 three times, then 0010
    pulse(lcd, false, false, 0x3);
    pulse(lcd, false, false, 0x3);
    pulse(lcd, false, false, 0x2);
    byte4(lcd, false, 0x28);
    byte4(lcd, false, 0x0C);
    byte4(lcd, false, 0x06);
    text4(lcd, "pitch (mm)");
    byte4(lcd, false, 0xC0);
    text4(lcd, "1.00");
    EXPECT_EQ(lcd.lines()[0], pad("pitch (mm)"));
    EXPECT_EQ(lcd.lines()[1], pad("1.00"));
    byte4(lcd, false, 0x80 | 0x27);  // the last character of line 1, off screen
    text4(lcd, "xy");                // 'y' lands at 0x40
    EXPECT_EQ(lcd.lines()[1], pad("y.00"));
    const std::uint64_t n = lcd.changes();
    byte4(lcd, false, 0x0C);  // an instruction that changes nothing visible
    EXPECT_EQ(lcd.changes(), n);
    byte4(lcd, false, 0x08);  // display off: nothing shows
    EXPECT_EQ(lcd.lines()[0], pad(""));
    EXPECT_EQ(lcd.changes(), n + 1);
}

// Datasheet "Display Data RAM": in 2-line mode line 1 is DDRAM 0x00..0x27 and line 2 is 0x40..0x67; the address
// counter runs on from 0x27 to 0x40 and from 0x67 back to 0x00, and the other way when it decrements. Shifted
// right by one, the display shows the 40th character of each line (0x27, 0x67) in column 0.
TEST(Hd44780, TwoLineAddressWrapsAtTheLineEnds) {
    Hd44780 lcd;
    pulse(lcd, false, false, 0x2);
    byte4(lcd, false, 0x28);  // 4-bit, 2 lines
    byte4(lcd, false, 0x0C);
    byte4(lcd, false, 0x06);         // increment
    byte4(lcd, false, 0x80 | 0x67);  // the last character of line 2
    text4(lcd, "ab");                // 'b' lands at 0x00
    EXPECT_EQ(lcd.lines()[0], pad("b"));
    byte4(lcd, false, 0x04);         // decrement
    byte4(lcd, false, 0x80 | 0x40);  // the first character of line 2
    text4(lcd, "cd");                // 'd' lands at 0x27
    byte4(lcd, false, 0x80 | 0x00);
    text4(lcd, "ef");  // 'f' lands at 0x67
    EXPECT_EQ(lcd.lines()[0], pad("e"));
    EXPECT_EQ(lcd.lines()[1], pad("c"));
    byte4(lcd, false, 0x1C);  // shift the display right
    EXPECT_EQ(lcd.lines()[0], pad("de"));
    EXPECT_EQ(lcd.lines()[1], pad("fc"));
}

// Datasheet "Display Data RAM": in 1-line mode the DDRAM is 0x00..0x4F, one line of 80 characters; the address
// counter runs on from 0x4F to 0x00, and from 0x00 back to 0x4F when it decrements.
TEST(Hd44780, OneLineAddressWrapsAt4F) {
    Hd44780 lcd;
    table12_init(lcd);  // 4-bit, 1 line, increment
    byte4(lcd, false, 0x80 | 0x4F);
    text4(lcd, "ab");  // 'b' lands at 0x00
    EXPECT_EQ(lcd.lines()[0], pad("b"));
    byte4(lcd, false, 0x04);  // decrement
    byte4(lcd, false, 0x80 | 0x01);
    text4(lcd, "cde");        // 'c' at 0x01, 'd' at 0x00, 'e' at 0x4F
    byte4(lcd, false, 0x1C);  // shift the display right: column 0 shows 0x4F
    EXPECT_EQ(lcd.lines()[0], pad("edc"));
}

}  // namespace
