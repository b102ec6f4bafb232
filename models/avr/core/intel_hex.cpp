#include "avr/core/intel_hex.hpp"

#include <fstream>
#include <sstream>

#include "common/bad_input.hpp"

namespace cnc::avr {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

}  // namespace

bool is_intel_hex(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char c = 0;
    return in.get(c) && c == ':';
}

std::vector<std::uint8_t> parse_intel_hex(std::string_view text, const std::string& file, std::size_t flash_bytes,
                                          const std::string& where) {
    std::vector<std::uint8_t> image;
    std::uint32_t base = 0;  // from the extended address records
    std::size_t line_no = 0;
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        ++line_no;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
        if (line.empty()) continue;
        const auto bad = [&](const std::string& why) {
            throw BadInput(where, file + ":" + std::to_string(line_no) + ": " + why +
                                      " (an Intel HEX record is "
                                      ":LLAAAATT, its data and a checksum, in hexadecimal digits)");
        };
        if (line[0] != ':' || line.size() < 11 || line.size() % 2 == 0) bad("not an Intel HEX record");
        std::vector<std::uint8_t> bytes;
        for (std::size_t i = 1; i < line.size(); i += 2) {
            const int hi = hex_digit(line[i]);
            const int lo = hex_digit(line[i + 1]);
            if (hi < 0 || lo < 0) bad("'" + std::string(line.substr(i, 2)) + "' is not a hexadecimal byte");
            bytes.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
        }
        const std::size_t length = bytes[0];
        if (bytes.size() != length + 5)
            bad("the record says " + std::to_string(length) + " data bytes, it has " +
                std::to_string(bytes.size() - 5));
        std::uint8_t sum = 0;
        for (const std::uint8_t b : bytes) sum = static_cast<std::uint8_t>(sum + b);
        if (sum != 0) bad("checksum wrong");
        const std::uint32_t address = static_cast<std::uint32_t>(bytes[1]) << 8 | bytes[2];
        const std::uint8_t type = bytes[3];
        const std::uint8_t* data = bytes.data() + 4;
        if (type == 0x00) {
            const std::size_t at = base + address;
            if (at + length > flash_bytes) {
                bad("data at 0x" + std::to_string(at) + " beyond the MCU's " + std::to_string(flash_bytes) +
                    "-byte flash");
            }
            if (image.size() < at + length) image.resize(at + length, 0xFF);
            for (std::size_t i = 0; i < length; ++i) image[at + i] = data[i];
        } else if (type == 0x01) {
            return image;
        } else if (type == 0x02 || type == 0x04) {
            if (length != 2) bad("an extended address record has 2 data bytes");
            const std::uint32_t value = static_cast<std::uint32_t>(data[0]) << 8 | data[1];
            base = type == 0x02 ? value << 4 : value << 16;
        } else if (type != 0x03 && type != 0x05) {
            bad("record type " + std::to_string(type) + " is not one of 00..05");
        }
    }
    throw BadInput(where, file + ": no end-of-file record (:00000001FF): the file is cut short");
}

std::vector<std::uint8_t> load_intel_hex(const std::string& path, std::size_t flash_bytes, const std::string& where) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadInput(where, "firmware HEX '" + path + "' not found or not readable");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_intel_hex(text.str(), path, flash_bytes, where);
}

}  // namespace cnc::avr
