// Intel HEX, the image grbl's Makefile and the Arduino IDE write (Intel "Hexadecimal Object File Format
// Specification" rev. A): records ":LLAAAATT<data>CC", with data (00), end of file (01), extended segment address (02)
// and extended linear address (04); start address records (03, 05) carry no image and are skipped. Each record's
// checksum makes the sum of its bytes 0 mod 256.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cnc::avr {

// Whether a firmware file is Intel HEX rather than ELF: by its first byte (':'), whatever its name.
[[nodiscard]] bool is_intel_hex(const std::string& path);

// The flash image from address 0 up to the last byte a data record writes (0xFF, erased flash, in gaps). Throws
// BadInput(where, ...) naming `file`'s line for a malformed record, a bad checksum, a missing end-of-file record, or
// data beyond `flash_bytes`.
[[nodiscard]] std::vector<std::uint8_t> parse_intel_hex(std::string_view text, const std::string& file,
                                                        std::size_t flash_bytes, const std::string& where);
// The same from a file (BadInput when it cannot be read).
[[nodiscard]] std::vector<std::uint8_t> load_intel_hex(const std::string& path, std::size_t flash_bytes,
                                                       const std::string& where);

}  // namespace cnc::avr
