#include "avr/core/data_access.hpp"

namespace cnc::avr {

namespace {

constexpr std::uint16_t kIoBase = 0x20;  // I/O address 0 is data address 0x20
constexpr std::uint16_t kSpl = 0x5D;

std::uint16_t pair(const std::uint8_t* data, int low) {
    return static_cast<std::uint16_t>(data[low] | (data[low + 1] << 8));
}

class Builder {
public:
    void read(std::uint16_t a) { add(a, true, false); }
    void write(std::uint16_t a) { add(a, false, true); }
    void read_write(std::uint16_t a) { add(a, true, true); }
    DataAccesses unmodelled() {
        m_out.unmodelled = true;
        return m_out;
    }
    [[nodiscard]] DataAccesses done() const { return m_out; }

private:
    void add(std::uint16_t a, bool r, bool w) { m_out.at[static_cast<std::size_t>(m_out.count++)] = {a, r, w}; }
    DataAccesses m_out;
};

// 1001 00sd dddd xxxx: LDS/STS, LD/ST through X, Y, Z with post-increment or pre-decrement, PUSH/POP, LPM/ELPM.
DataAccesses load_store(std::uint16_t op, std::uint16_t next_word, const std::uint8_t* data) {
    Builder b;
    const bool store = (op & 0x0200) != 0;
    const std::uint16_t sp = pair(data, kSpl);
    const auto access = [&](std::uint16_t a) { store ? b.write(a) : b.read(a); };
    const auto x = pair(data, 26);
    const auto y = pair(data, 28);
    const auto z = pair(data, 30);
    switch (op & 0x000F) {
        case 0x0:
            access(next_word);  // LDS / STS
            break;
        case 0x1:
            access(z);  // Z+
            break;
        case 0x2:
            access(static_cast<std::uint16_t>(z - 1));  // -Z
            break;
        case 0x4:
        case 0x5:
            if (store) return b.unmodelled();  // XCH, LAS: not on the ATmega328P
            break;                             // LPM Z, LPM Z+: flash
        case 0x9:
            access(y);
            break;
        case 0xA:
            access(static_cast<std::uint16_t>(y - 1));
            break;
        case 0xC:
        case 0xD:
            access(x);
            break;
        case 0xE:
            access(static_cast<std::uint16_t>(x - 1));
            break;
        case 0xF:
            if (store)
                b.write(sp);  // PUSH: at SP, then SP - 1
            else
                b.read(static_cast<std::uint16_t>(sp + 1));  // POP
            break;
        default:
            return b.unmodelled();  // ELPM, LAC, LAT, reserved
    }
    return b.done();
}

}  // namespace

DataAccesses data_accesses(std::uint16_t op, std::uint16_t next_word, const std::uint8_t* data) {
    Builder b;
    const std::uint16_t sp = pair(data, kSpl);
    if ((op & 0xD000) == 0x8000) {  // LDD / STD (and LD/ST Y, Z): 10q0 qqsd dddd bqqq
        const int q = ((op >> 8) & 0x20) | ((op >> 7) & 0x18) | (op & 0x7);
        const std::uint16_t base = pair(data, (op & 0x0008) != 0 ? 28 : 30);
        const auto a = static_cast<std::uint16_t>(base + q);
        (op & 0x0200) != 0 ? b.write(a) : b.read(a);
        return b.done();
    }
    if ((op & 0xFC00) == 0x9000) return load_store(op, next_word, data);
    if ((op & 0xF000) == 0xB000) {  // IN / OUT: 1011 sAAd dddd AAAA
        const auto a = static_cast<std::uint16_t>(kIoBase + (((op >> 5) & 0x30) | (op & 0x0F)));
        (op & 0x0800) != 0 ? b.write(a) : b.read(a);
        return b.done();
    }
    if ((op & 0xFC00) == 0x9800) {  // CBI, SBIC, SBI, SBIS: 1001 10xx AAAA Abbb
        const auto a = static_cast<std::uint16_t>(kIoBase + ((op >> 3) & 0x1F));
        (op & 0x0100) != 0 ? b.read(a) : b.read_write(a);
        return b.done();
    }
    const bool call = (op & 0xFE0E) == 0x940E || (op & 0xF000) == 0xD000 || op == 0x9509;  // CALL, RCALL, ICALL
    if (call) {
        b.write(sp);  // the return address, low byte first (simavr's _avr_push_addr)
        b.write(static_cast<std::uint16_t>(sp - 1));
        return b.done();
    }
    if (op == 0x9508 || op == 0x9518) {  // RET, RETI
        b.read(static_cast<std::uint16_t>(sp + 1));
        b.read(static_cast<std::uint16_t>(sp + 2));
        return b.done();
    }
    // SLEEP, BREAK, WDR, SPM, EICALL, EIJMP, DES (1001 0100 kkkk 1011)
    const bool special = op == 0x9588 || op == 0x9598 || op == 0x95A8 || op == 0x95E8 || op == 0x95F8 || op == 0x9519 ||
                         op == 0x9419 || (op & 0xFF0F) == 0x940B;
    if (special) return b.unmodelled();
    return b.done();
}

}  // namespace cnc::avr
