#include "architectures/rtl/rtl_settings.hpp"

#include <regex>
#include <string>

namespace cnc::sim {

namespace fs = std::filesystem;

namespace {

std::string existing_file(KeyReader& r, const fs::path& base, const std::string& key, const std::string& path) {
    const std::string resolved = (base / path).lexically_normal().string();
    if (!fs::is_regular_file(resolved)) r.fail(key, resolved + " is not a file");
    return resolved;
}

}  // namespace

void read_rtl_settings(KeyReader& r, const fs::path& base, const std::string& prefix, RtlSettings& s) {
    s.rtl = r.get_choice("fpga.model", "event", {"event", "rtl"},
                         "the FPGA (of both FPGA architectures: one key) as event-driven SystemC blocks, or its "
                         "Verilog verilated and clocked in the loop (needs Verilator; the first run of a design "
                         "builds it, about 15 s)") == "rtl";
    const std::string top_key = prefix + ".rtl_top";
    const std::string sources_key = prefix + ".rtl_sources";
    const std::string parameters_key = prefix + ".rtl_parameters";
    const std::string top = r.get_string(
        top_key, "",
        "the user's top module's file (the module named as the file) with our top's ports; empty: our Verilog");
    const std::vector<std::string> sources =
        r.get_string_list(sources_key, "the user's other Verilog files, relative to the scenario");
    const std::vector<std::string> parameters = r.get_string_list(
        parameters_key,
        "top parameter overrides, NAME=VALUE (a Verilog number), after those set from the " + prefix + " keys");
    const bool any = !top.empty() || !sources.empty() || !parameters.empty();
    if (any && !s.rtl) r.fail("fpga.model", top_key + ", " + sources_key + " and " + parameters_key + " need \"rtl\"");
    if (!top.empty()) s.design.top_file = existing_file(r, base, top_key, top);
    if (!sources.empty() && top.empty()) r.fail(sources_key, "needs " + top_key);
    for (const std::string& src : sources) s.design.sources.push_back(existing_file(r, base, sources_key, src));
    static const std::regex assignment(R"(([A-Za-z_]\w*)=([0-9][0-9_]*|[0-9]*'[sS]?[bBoOdDhH][0-9a-fA-F_xXzZ]+))");
    for (const std::string& p : parameters) {
        std::smatch m;
        if (!std::regex_match(p, m, assignment)) {
            r.fail(parameters_key, "\"" + p + "\" is not NAME=VALUE with a Verilog number (PULSE_HIGH=120)");
        }
        s.design.parameters.emplace_back(m[1].str(), m[2].str());
    }
    s.design.where = r.where(top.empty() ? "fpga.model" : top_key);
#ifndef CNC_WITH_VERILATOR
    if (s.rtl) r.fail("fpga.model", "this cncsim was built without Verilator (CNC_WITH_VERILATOR): \"event\" only");
#endif
}

}  // namespace cnc::sim
