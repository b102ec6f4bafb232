// Text from a user's file in a message: control bytes and bytes that are not UTF-8 would reach the terminal raw
// (an ESC starts an escape sequence, a NUL or CR hides what follows), so every message escapes them as \xNN.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace cnc {

// Length of the valid UTF-8 sequence of 2 to 4 bytes starting at text[i], 0 if there is none. The table is
// RFC 3629 §4's: per lead byte, the length and the range of the second byte (no overlong forms, no surrogates,
// nothing past U+10FFFF); further bytes are 0x80..0xBF.
inline std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
    struct Lead {
        unsigned char lead_min, lead_max;
        std::size_t length;
        unsigned char second_min, second_max;
    };
    static constexpr Lead kLeads[] = {{0xC2, 0xDF, 2, 0x80, 0xBF}, {0xE0, 0xE0, 3, 0xA0, 0xBF},
                                      {0xE1, 0xEC, 3, 0x80, 0xBF}, {0xED, 0xED, 3, 0x80, 0x9F},
                                      {0xEE, 0xEF, 3, 0x80, 0xBF}, {0xF0, 0xF0, 4, 0x90, 0xBF},
                                      {0xF1, 0xF3, 4, 0x80, 0xBF}, {0xF4, 0xF4, 4, 0x80, 0x8F}};
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    for (const Lead& l : kLeads) {
        if (byte(i) < l.lead_min || byte(i) > l.lead_max) continue;
        if (i + l.length > text.size() || byte(i + 1) < l.second_min || byte(i + 1) > l.second_max) return 0;
        for (std::size_t k = 2; k < l.length; ++k) {
            if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
        }
        return l.length;
    }
    return 0;
}

// `text` with every byte that is neither printable ASCII, a line feed (messages list problems a line each)
// nor part of a valid UTF-8 character written as \xNN.
inline std::string printable(std::string_view text) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c >= 0x20 && c < 0x7F) || c == '\n') {
            out.push_back(static_cast<char>(c));
            ++i;
        } else if (const std::size_t n = c >= 0x80 ? utf8_sequence_length(text, i) : 0; n > 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            out += "\\x";
            out.push_back(kHex[c >> 4]);
            out.push_back(kHex[c & 0xF]);
            ++i;
        }
    }
    return out;
}

}  // namespace cnc
