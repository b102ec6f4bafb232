// Seed 002's 4x4 keypad matrix (§6.6): columns 1..4 on PB7..PB4 (outputs), rows 1..4 on PB3..PB0 (inputs with
// pull-ups); a pressed key joins its column to its row.
#pragma once
#include <string>

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

}  // namespace cnc::lathe
