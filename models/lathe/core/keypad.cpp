#include "lathe/core/keypad.hpp"

namespace cnc::lathe {

namespace {
constexpr const char* kKeys = "147*2580369#ABCD";
}

bool keypad_has(char key) {
    return key != '\0' && std::string(kKeys).find(key) != std::string::npos;
}

std::string keypad_keys() {
    return kKeys;
}

KeyPos key_pos(char key) {
    const auto i = std::string(kKeys).find(key);
    if (key == '\0' || i == std::string::npos) return {-1, -1};
    return {static_cast<int>(i / 4), static_cast<int>(i % 4)};
}

std::array<bool, 4> KeypadMatrix::rows(const std::array<bool, 4>& columns) const {
    std::array<bool, 4> high{true, true, true, true};
    for (const KeyPos& k : m_pressed) {
        if (!columns[static_cast<std::size_t>(k.col)]) high[static_cast<std::size_t>(k.row)] = false;
    }
    return high;
}

}  // namespace cnc::lathe
