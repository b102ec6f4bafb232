// Seed 002's 4x4 keypad matrix (§2.5.3): columns 1..4 on PB7..PB4 (outputs), rows 1..4 on PB3..PB0 (inputs with
// pull-ups); a pressed key joins its column to its row.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace cnc::lathe {

struct KeyPos {
    int col;  // 0..3 = PB7..PB4
    int row;  // 0..3 = PB3..PB0
};

[[nodiscard]] bool keypad_has(char key);
// The key at each position, column by column: "147*2580369#ABCD" ('#' is the decimal point).
[[nodiscard]] std::string keypad_keys();
// {-1, -1} for a key the keypad lacks.
[[nodiscard]] KeyPos key_pos(char key);

// The matrix itself: a pressed key's switch joins its column line to its row line; the rows are pulled up (the
// MCU's PORTB pull-ups), so a row reads low while a pressed key joins it to a column the MCU drives low.
class KeypadMatrix {
public:
    void press(char key) { m_pressed.push_back(key_pos(key)); }
    void release_all() { m_pressed.clear(); }
    // Rows 1..4 (PB3..PB0) from columns 1..4 (PB7..PB4), true = high.
    [[nodiscard]] std::array<bool, 4> rows(const std::array<bool, 4>& columns) const;

private:
    std::vector<KeyPos> m_pressed;
};

}  // namespace cnc::lathe
