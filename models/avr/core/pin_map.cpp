#include "avr/core/pin_map.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <utility>

#include "common/bad_input.hpp"

namespace cnc::avr {

namespace {

// "PB0..PB7, PC0..PC6, PD2..PD7": the pins a map may name (PD0/PD1 are the USART's).
std::string pins_that_exist(const McuMap& m) {
    std::string out;
    for (const PortAddr& p : m.ports) {
        const int first = p.port == 'D' ? 2 : 0;
        out += (out.empty() ? "" : ", ") + std::string{'P', p.port, static_cast<char>('0' + first)} + ".." +
               std::string{'P', p.port, static_cast<char>('0' + p.bits - 1)};
    }
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())) != 0) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())) != 0) s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string signal_list() {
    std::string out;
    for (const auto s : kPinSignals) out += (out.empty() ? "" : ", ") + std::string(s);
    return out;
}

}  // namespace

Pin parse_pin(std::string_view text, const std::string& where, Mcu mcu) {
    const McuMap& m = mcu_map(mcu);
    const std::string_view t = trim(text);
    const auto bad = [&](const std::string& why) {
        return BadInput(
            where, "pin '" + std::string(t) + "' " + why + " (" + m.display + " pins: " + pins_that_exist(m) + ")");
    };
    if (t.size() != 3 || std::toupper(static_cast<unsigned char>(t[0])) != 'P' ||
        std::isdigit(static_cast<unsigned char>(t[2])) == 0)
        throw bad("is not a port pin name like PD6");
    const char port = static_cast<char>(std::toupper(static_cast<unsigned char>(t[1])));
    const int bit = t[2] - '0';
    const auto p = std::find_if(m.ports.begin(), m.ports.end(), [port](const PortAddr& a) { return a.port == port; });
    if (p == m.ports.end()) throw bad("names a port the " + std::string(m.display) + " does not have");
    if (bit >= p->bits) throw bad("does not exist");
    if (port == 'D' && bit < 2) throw bad("is the USART's " + std::string(bit == 0 ? "RXD" : "TXD") + " pin");
    return Pin{port, bit};
}

std::string PinMap::to_string() const {
    std::string out;
    for (const auto s : kPinSignals) out += (out.empty() ? "" : ",") + std::string(s) + "=" + at(s).name();
    return out;
}

PinMap default_pin_map() {
    PinMap m;
    m.pins = {{"step_x", {'D', 6}}, {"dir_x", {'B', 0}}, {"en_x", {'B', 2}}, {"step_y", {'B', 3}},
              {"dir_y", {'B', 5}},  {"en_y", {'B', 4}},  {"head", {'B', 1}}};
    return m;
}

PinMap timer1_y_pin_map() {
    PinMap m = default_pin_map();
    m.pins["step_y"] = {'B', 1};
    m.pins["head"] = {'B', 3};
    return m;
}

PinMap grbl_pin_map() {
    PinMap m;
    m.pins = {{"step_x", {'D', 2}}, {"dir_x", {'D', 5}}, {"en_x", {'B', 0}}, {"step_y", {'D', 3}},
              {"dir_y", {'D', 6}},  {"en_y", {'B', 0}},  {"head", {'B', 3}}};
    return m;
}

PinMap grbl_atmega16_pin_map() {
    PinMap m;
    m.pins = {{"step_x", {'A', 0}}, {"dir_x", {'A', 2}}, {"en_x", {'A', 4}}, {"step_y", {'A', 1}},
              {"dir_y", {'A', 3}},  {"en_y", {'A', 4}},  {"head", {'D', 7}}};
    return m;
}

PinMap parse_pin_map(std::string_view text, const std::string& where) {
    return parse_pin_map(text, where, default_pin_map());
}

PinMap parse_pin_map(std::string_view text, const std::string& where, PinMap defaults, Mcu mcu) {
    PinMap m = std::move(defaults);
    std::set<std::string> named;
    std::string_view rest = text;
    while (!trim(rest).empty()) {
        const std::size_t comma = rest.find(',');
        const std::string_view entry = trim(rest.substr(0, comma));
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
        const std::size_t eq = entry.find('=');
        if (eq == std::string_view::npos)
            throw BadInput(where, "pin map entry '" + std::string(entry) + "' is not signal=pin");
        const std::string signal = lower(trim(entry.substr(0, eq)));
        if (std::find(kPinSignals.begin(), kPinSignals.end(), signal) == kPinSignals.end())
            throw BadInput(where, "unknown signal '" + signal + "' in the pin map (signals: " + signal_list() + ")");
        if (!named.insert(signal).second) throw BadInput(where, "signal '" + signal + "' is mapped twice");
        m.pins[signal] = parse_pin(entry.substr(eq + 1), where, mcu);
    }
    validate(m, where, mcu);
    return m;
}

void validate(const PinMap& map, const std::string& where, Mcu mcu) {
    for (const auto s : kPinSignals)
        if (map.pins.count(std::string(s)) == 0) throw BadInput(where, "the pin map has no '" + std::string(s) + "'");
    if (map.pins.size() != kPinSignals.size()) throw BadInput(where, "the pin map names unknown signals");
    for (const auto& [signal, pin] : map.pins) (void)parse_pin(pin.name(), where, mcu);
    for (const auto& [a, pa] : map.pins)
        for (const auto& [b, pb] : map.pins)
            if (a < b && pa == pb && !(a == "en_x" && b == "en_y"))
                throw BadInput(where, "signals '" + a + "' and '" + b + "' are both on " + pa.name());
}

}  // namespace cnc::avr
