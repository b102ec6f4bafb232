#include "avr/core/elf_check.hpp"

#include <fstream>
#include <iterator>
#include <vector>

#include "avr/core/mcu_map.hpp"
#include "common/bad_input.hpp"

namespace cnc::avr {

namespace {

// ELF specification (System V gABI) header layout and the values used here.
constexpr std::uint16_t kEmAvr = 83;            // EM_AVR
constexpr std::uint32_t kEfAvrMachMask = 0x7F;  // EF_AVR_MACH (binutils include/elf/avr.h)
constexpr std::size_t kElf32HeaderBytes = 52;
constexpr std::size_t kElf32SectionHeaderBytes = 40;
constexpr std::uint8_t kMmcuTagName = 1;       // simavr avr_mcu_section.h: AVR_MMCU_TAG_NAME
constexpr std::uint8_t kMmcuTagFrequency = 2;  // AVR_MMCU_TAG_FREQUENCY

std::string machine_name(std::uint16_t m) {
    switch (m) {
        case 3:
            return "x86 (i386)";
        case 40:
            return "ARM";
        case 62:
            return "x86-64";
        case 183:
            return "AArch64";
        case 243:
            return "RISC-V";
        default:
            return "machine " + std::to_string(m);
    }
}

class Bytes {
public:
    explicit Bytes(std::vector<std::uint8_t> b) : m_b(std::move(b)) {}
    [[nodiscard]] std::size_t size() const { return m_b.size(); }
    [[nodiscard]] bool has(std::size_t off, std::size_t n) const { return off <= m_b.size() && n <= m_b.size() - off; }
    [[nodiscard]] std::uint8_t u8(std::size_t off) const { return m_b.at(off); }
    [[nodiscard]] std::uint16_t u16(std::size_t off) const {
        return static_cast<std::uint16_t>(u8(off) | (u8(off + 1) << 8));
    }
    [[nodiscard]] std::uint32_t u32(std::size_t off) const {
        return static_cast<std::uint32_t>(u16(off)) | (static_cast<std::uint32_t>(u16(off + 2)) << 16);
    }

private:
    std::vector<std::uint8_t> m_b;
};

struct Section {
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
};

// Finds a section by name in a little-endian ELF32 file; size 0 when absent or the table is damaged.
Section find_section(const Bytes& f, const std::string& wanted) {
    const std::uint32_t shoff = f.u32(32);
    const std::uint16_t shentsize = f.u16(46);
    const std::uint16_t shnum = f.u16(48);
    const std::uint16_t shstrndx = f.u16(50);
    if (shentsize < kElf32SectionHeaderBytes || shstrndx >= shnum ||
        !f.has(shoff, static_cast<std::size_t>(shnum) * shentsize))
        return {};
    const auto header = [&](std::size_t i) { return shoff + i * shentsize; };
    const std::uint32_t strtab = f.u32(header(shstrndx) + 16);
    for (std::size_t i = 0; i < shnum; ++i) {
        const std::size_t name_off = static_cast<std::size_t>(strtab) + f.u32(header(i));
        std::string name;
        for (std::size_t k = name_off; f.has(k, 1) && f.u8(k) != 0; ++k) name += static_cast<char>(f.u8(k));
        if (name != wanted) continue;
        const Section s{f.u32(header(i) + 16), f.u32(header(i) + 20)};
        return f.has(s.offset, s.size) ? s : Section{};
    }
    return {};
}

// simavr's .mmcu section: {tag, len, payload[len]} records (sim_elf.c reads it the same way).
void read_mmcu(const Bytes& f, Section s, ElfInfo& info) {
    std::size_t at = s.offset;
    const std::size_t end = static_cast<std::size_t>(s.offset) + s.size;
    while (at + 2 <= end) {
        const std::uint8_t tag = f.u8(at);
        const std::size_t len = f.u8(at + 1);
        const std::size_t payload = at + 2;
        if (payload + len > end) break;
        if (tag == kMmcuTagName) {
            std::string name;
            for (std::size_t k = payload; k < payload + len && f.u8(k) != 0; ++k) name += static_cast<char>(f.u8(k));
            info.mmcu = name;
            info.mmcu_source = ".mmcu section";
        } else if (tag == kMmcuTagFrequency && len >= 4) {
            info.frequency_hz = f.u32(payload);
        }
        at = payload + len;
    }
}

// avr-libc's crt .note.gnu.avr.deviceinfo: an ELF note (namesz, descsz, type, "AVR\0") whose descriptor holds the
// flash, SRAM and EEPROM start and size (6 words), then the string table's offset-table length and the device name's
// offset into the string table, which follows at descriptor + 32.
void read_device_note(const Bytes& f, Section s, ElfInfo& info) {
    constexpr std::size_t kNameOffsetWord = 28;
    constexpr std::size_t kStringTable = 32;
    if (s.size < 16) return;
    const std::uint32_t namesz = f.u32(s.offset);
    const std::uint32_t descsz = f.u32(s.offset + 4);
    const std::size_t desc = s.offset + 12 + ((static_cast<std::size_t>(namesz) + 3) / 4) * 4;
    const std::size_t end = static_cast<std::size_t>(s.offset) + s.size;
    if (namesz != 4 || f.u32(s.offset + 12) != 0x00525641U /* "AVR\0" */ || descsz <= kStringTable ||
        desc + descsz > end)
        return;
    std::string name;
    for (std::size_t k = desc + kStringTable + f.u32(desc + kNameOffsetWord); k < desc + descsz && f.u8(k) != 0; ++k)
        name += static_cast<char>(f.u8(k));
    if (!name.empty()) {
        info.mmcu = name;
        info.mmcu_source = ".note.gnu.avr.deviceinfo section";
    }
}

}  // namespace

std::string mcu_named(const std::string& mcu, const std::string& mcu_key) {
    return mcu_key.empty() ? "the model is an " + mcu : mcu_key + " is " + mcu;
}

ElfInfo check_avr_elf(const std::string& path, const std::string& mcu, std::uint32_t f_cpu_hz, const std::string& where,
                      const std::string& mcu_key) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadInput(where, "firmware ELF '" + path + "' not found or not readable");
    const Bytes f(std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {}));
    if (f.size() < 4 || f.u8(0) != 0x7F || f.u8(1) != 'E' || f.u8(2) != 'L' || f.u8(3) != 'F')
        throw BadInput(where, "firmware '" + path + "' is not an ELF file (no \\x7fELF magic)");
    if (f.size() < kElf32HeaderBytes) throw BadInput(where, "firmware ELF '" + path + "' is truncated");
    const bool little_endian = f.u8(5) == 1;
    const std::uint16_t machine = little_endian ? f.u16(18) : static_cast<std::uint16_t>((f.u8(18) << 8) | f.u8(19));
    if (machine != kEmAvr)
        throw BadInput(where, "firmware '" + path + "' is an ELF for " + machine_name(machine) + ", not for the AVR");
    if (f.u8(4) != 1 || !little_endian)
        throw BadInput(where, "firmware ELF '" + path + "' is not a 32-bit little-endian AVR ELF");

    ElfInfo info;
    info.avr_arch = static_cast<int>(f.u32(36) & kEfAvrMachMask);
    const Section mmcu = find_section(f, ".mmcu");
    if (mmcu.size > 0) read_mmcu(f, mmcu, info);
    if (info.mmcu.empty()) {
        const Section note = find_section(f, ".note.gnu.avr.deviceinfo");
        if (note.size > 0) read_device_note(f, note, info);
    }
    if (!info.mmcu.empty() && info.mmcu != mcu)
        throw BadInput(where, "firmware '" + path + "' was built for " + info.mmcu + " (its " + info.mmcu_source +
                                  "), " + mcu_named(mcu, mcu_key));
    const auto modelled = mcu_by_name(mcu);
    const int arch = modelled ? mcu_map(*modelled).avr_arch : 0;
    if (info.mmcu.empty() && info.avr_arch != arch)
        throw BadInput(where, "firmware '" + path + "' was built for AVR architecture avr" +
                                  std::to_string(info.avr_arch) + ", the " + mcu + " is avr" + std::to_string(arch) +
                                  " (" + mcu_named(mcu, mcu_key) + ")");
    if (info.frequency_hz != 0 && info.frequency_hz != f_cpu_hz)
        throw BadInput(where, "firmware '" + path + "' declares F_CPU " + std::to_string(info.frequency_hz) +
                                  " Hz (.mmcu section), the chip runs at " + std::to_string(f_cpu_hz) + " Hz");
    return info;
}

}  // namespace cnc::avr
