#include "rtl/verilated_ports.hpp"

#include <algorithm>
#include <regex>

#include "common/bad_input.hpp"

namespace cnc::rtl {

std::vector<VerilatedPort> parse_verilated_ports(const std::string& header_text) {
    // Verilator 5: VL_IN8(&name,msb,lsb); VL_OUT16, VL_IN (32 bits), VL_OUT64, VL_INW(&name,msb,lsb,words) ...
    static const std::regex decl(R"(VL_(IN|OUT)(8|16|64|W)?\(&(\w+),(\d+),(\d+)[,)])");
    std::vector<VerilatedPort> ports;
    for (auto it = std::sregex_iterator(header_text.begin(), header_text.end(), decl); it != std::sregex_iterator();
         ++it) {
        const std::smatch& m = *it;
        ports.push_back({m[3].str(), std::stoi(m[4].str()) - std::stoi(m[5].str()) + 1, m[1].str() == "IN"});
    }
    return ports;
}

std::vector<std::string> declared_parameters(const std::string& verilog_text) {
    static const std::regex decl(R"(\bparameter\s+(?:integer\s+|signed\s+)?(?:\[[^\]]*\]\s*)?([A-Za-z_]\w*)\s*=)");
    std::vector<std::string> names;
    for (auto it = std::sregex_iterator(verilog_text.begin(), verilog_text.end(), decl); it != std::sregex_iterator();
         ++it) {
        names.push_back((*it)[1].str());
    }
    return names;
}

namespace {

std::string describe(const char* dir, const RtlPort& p) {
    return std::string(dir) + " " + p.name + " (" + std::to_string(p.width) + (p.width == 1 ? " bit)" : " bits)");
}

void expect(const PluginSpec& spec, const std::vector<VerilatedPort>& ports, const RtlPort& want, bool input) {
    const char* dir = input ? "input" : "output";
    const auto found =
        std::find_if(ports.begin(), ports.end(), [&](const VerilatedPort& p) { return p.name == want.name; });
    if (found == ports.end() && want.optional) return;
    if (found == ports.end()) {
        throw BadInput(spec.where, "module " + spec.top_module + " has no port " + want.name + ": expected " +
                                       describe(dir, want));
    }
    if (found->input != input || found->width != want.width) {
        throw BadInput(spec.where, "port " + want.name + " of module " + spec.top_module + " is " +
                                       describe(found->input ? "input" : "output", {want.name, found->width}) +
                                       ": expected " + describe(dir, want));
    }
}

}  // namespace

void check_ports(const PluginSpec& spec, const std::vector<VerilatedPort>& ports) {
    expect(spec, ports, {spec.clock, 1}, true);
    for (const RtlPort& p : spec.inputs) expect(spec, ports, p, true);
    for (const RtlPort& p : spec.outputs) expect(spec, ports, p, false);
    for (const VerilatedPort& p : ports) {
        if (!p.input || p.name == spec.clock) continue;
        const bool driven = std::any_of(spec.inputs.begin(), spec.inputs.end(),
                                        [&](const RtlPort& want) { return want.name == p.name; });
        if (!driven) {
            throw BadInput(spec.where, "input " + p.name + " of module " + spec.top_module +
                                           " is not driven by the simulation (its inputs: " + spec.clock +
                                           [&] {
                                               std::string names;
                                               for (const RtlPort& want : spec.inputs) names += ", " + want.name;
                                               return names;
                                           }() +
                                           ")");
        }
    }
}

}  // namespace cnc::rtl
