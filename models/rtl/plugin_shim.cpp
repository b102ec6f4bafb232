#include "rtl/plugin_shim.hpp"

#include <sstream>

namespace cnc::rtl {

std::string root_member(const std::string& top_module, const ObservedNet& net) {
    std::string member = top_module + "__DOT__";
    for (const char c : net.path) member += c == '.' ? std::string("__DOT__") : std::string(1, c);
    return member;
}

std::string public_nets_config(const PluginSpec& spec) {
    std::ostringstream vlt;
    vlt << "`verilator_config\n";
    for (const ObservedNet& n : spec.observed) {
        vlt << "public_flat_rd -module \"" << n.module << "\" -var \"" << n.var << "\"\n";
    }
    return vlt.str();
}

namespace {

std::string collapse_spaces(const std::string& text) {
    std::string out;
    bool space = false;
    for (const char c : text) {
        if (c == ' ' || c == '\n' || c == '\t') {
            space = true;
            continue;
        }
        if (space && !out.empty()) out += ' ';
        space = false;
        out += c;
    }
    return out;
}

}  // namespace

bool rising_edge_only(const std::string& root_header, const std::string& sources, const std::string& prefix,
                      const std::string& clock) {
    const std::string prev = "__Vtrigrprev__TOP__" + clock;
    const std::string code = collapse_spaces(sources);
    return root_header.find("VlTriggerVec<1> __VactTriggered;") != std::string::npos &&
           root_header.find(" " + prev + ";") != std::string::npos &&
           root_header.find("__VicoTriggered") == std::string::npos &&
           code.find("vlSelf->__VactTriggered.at(0U) = ((IData)(vlSelf->" + clock + ") & (~ (IData)(vlSelf->" + prev +
                     ")));") != std::string::npos &&
           code.find("void " + prefix + "___024root___eval(" + prefix + "___024root* vlSelf) {") != std::string::npos;
}

std::string shim_source(const PluginSpec& spec, const std::string& prefix, const std::vector<bool>& present,
                        const std::vector<bool>& inputs_present, bool rising_only) {
    std::vector<std::string> watched;  // C++ expressions, outputs first
    for (const RtlPort& p : spec.outputs) watched.push_back("m_top." + p.name);
    for (std::size_t i = 0; i < spec.observed.size(); ++i) {
        if (present[i]) watched.push_back("m_top.rootp->" + root_member(spec.top_module, spec.observed[i]));
    }
    std::ostringstream s;
    s << "// Written by cncsim for module " << spec.top_module << ".\n"
      << "#include <cstdint>\n#include <cstring>\n#include \"verilated.h\"\n#include \"" << prefix << ".h\"\n#include \"" << prefix
      << "___024root.h\"\n#include \"rtl/rtl_model.hpp\"\n\nnamespace {\n\n"
      << "constexpr int kWatched = " << watched.size() << ";\n\n"
      << "class Model final : public cnc::rtl::RtlModel {\npublic:\n"
      << "    Model() : m_top(&m_ctx, \"" << spec.top_module << "\") {\n"
      << "        m_top." << spec.clock << " = 0;\n        m_top.eval();\n    }\n"
      << "    ~Model() override { m_top.final(); }\n"
      << "    void set_input(int input, std::uint64_t value) override {\n        m_settled = false;\n"
      << "        switch (input) {\n";
    for (std::size_t i = 0; i < spec.inputs.size(); ++i) {
        if (!inputs_present[i]) continue;
        s << "            case " << i << ": m_top." << spec.inputs[i].name << " = value; break;\n";
    }
    s << "            default: break;\n        }\n    }\n"
      << "    std::uint64_t run(std::uint64_t max_cycles) override {\n"
      << "        std::uint64_t before[kWatched > 0 ? kWatched : 1];\n"
      << "        for (int i = 0; i < kWatched; ++i) before[i] = value(i);\n"
      << "        m_settled = false;\n"
      << "        for (std::uint64_t c = 1; c <= max_cycles; ++c) {\n"
      << "            // The whole state around the batch's last edge: unchanged means a fixed point.\n"
      << "            if (c == max_cycles) std::memcpy(m_state, static_cast<const void*>(m_top.rootp), sizeof m_state);\n"
      << "            tick();\n"
      << "            if (changed(before)) return c;\n        }\n"
      << "        m_settled = std::memcmp(m_state, static_cast<const void*>(m_top.rootp), sizeof m_state) == 0;\n"
      << "        return max_cycles;\n    }\n"
      << "    bool settled() const override { return m_settled; }\n"
      << "    std::uint64_t value(int watched) const override {\n        switch (watched) {\n";
    for (std::size_t i = 0; i < watched.size(); ++i) {
        s << "            case " << i << ": return static_cast<std::uint64_t>(" << watched[i] << ");\n";
    }
    s << "            default: return 0;\n        }\n    }\n\nprivate:\n"
      << "    void tick() {\n        m_top." << spec.clock << " = 1;\n";
    if (rising_only) {
        // Nothing reacts to the falling edge: it is only recorded where the trigger looks for it, and the root is
        // evaluated without eval_step's bookkeeping (a thread-local task id and the threads' message queue: the
        // model runs on one thread).
        s << "        " << prefix << "___024root___eval(m_top.rootp);\n"
          << "        m_top." << spec.clock << " = 0;\n"
          << "        m_top.rootp->__Vtrigrprev__TOP__" << spec.clock << " = 0;\n    }\n";
    } else {
        s << "        m_top.eval();\n        m_top." << spec.clock << " = 0;\n        m_top.eval();\n    }\n";
    }
    // One test per edge for all the watched values, not a branch each.
    s << "    bool changed(const std::uint64_t* before) const {\n        std::uint64_t diff = 0;\n";
    for (std::size_t i = 0; i < watched.size(); ++i) {
        s << "        diff |= static_cast<std::uint64_t>(" << watched[i] << ") ^ before[" << i << "];\n";
    }
    s << "        return diff != 0;\n    }\n    VerilatedContext m_ctx;\n    " << prefix << " m_top;\n"
      << "    unsigned char m_state[sizeof(" << prefix << "___024root)];\n    bool m_settled = false;\n};\n\n"
      << "}  // namespace\n\n"
      << "#define CNCSIM_EXPORT extern \"C\" __attribute__((visibility(\"default\")))\n"
      << "CNCSIM_EXPORT cnc::rtl::RtlModel* cncsim_rtl_create() { return new Model(); }\n"
      << "CNCSIM_EXPORT int cncsim_rtl_abi() { return cnc::rtl::kAbiVersion; }\n";
    return s.str();
}

}  // namespace cnc::rtl
