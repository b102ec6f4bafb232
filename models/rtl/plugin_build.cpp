#include "rtl/plugin_build.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/bad_input.hpp"
#include "rtl/plugin_shim.hpp"
#include "rtl/rtl_model.hpp"
#include "rtl/verilated_ports.hpp"

namespace cnc::rtl {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPrefix = "Vcncsim_top";

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

std::string cxx_flags();

// FNV-1a, 64 bits: a stable key across runs and builds (std::hash is not promised to be).
struct Fnv {
    std::uint64_t h = 1469598103934665603ULL;
    void add(const std::string& s) {
        for (const char c : s) {
            h ^= static_cast<unsigned char>(c);
            h *= 1099511628211ULL;
        }
        h ^= 0xff;  // a separator, so "ab"+"c" and "a"+"bc" differ
        h *= 1099511628211ULL;
    }
};

std::string cache_key(const PluginSpec& spec) {
    Fnv f;
    f.add(std::to_string(kAbiVersion));
    f.add(CNC_VERILATOR_BIN);
    // What this cncsim writes around the design (a change to the shim's generator is another plug-in).
    for (const bool rising_only : {false, true}) {
        f.add(shim_source(spec, kPrefix, std::vector<bool>(spec.observed.size(), true),
                          std::vector<bool>(spec.inputs.size(), true), rising_only));
    }
    f.add(cxx_flags());
    f.add(read_text(fs::path(CNC_MODELS_DIR) / "rtl" / "rtl_model.hpp"));
    f.add(spec.top_module);
    for (const std::string& src : spec.sources) {
        if (!fs::is_regular_file(src)) throw BadInput(spec.where, "cannot read Verilog source " + src);
        f.add(read_text(src));
    }
    for (const auto& [name, value] : spec.parameters) f.add(name + "=" + value);
    f.add(spec.clock);
    for (const RtlPort& p : spec.inputs) f.add("i" + p.name + std::to_string(p.width) + (p.optional ? "?" : ""));
    for (const RtlPort& p : spec.outputs) f.add("o" + p.name + std::to_string(p.width));
    for (const ObservedNet& n : spec.observed) f.add(n.module + "." + n.path + "." + n.var);
    std::ostringstream hex;
    hex << std::hex << f.h;
    return hex.str();
}

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// Runs `command` with its output in `log`; true on exit status 0.
bool run(const std::string& command, const fs::path& log) {
    return std::system((command + " >" + quoted(log.string()) + " 2>&1").c_str()) == 0;
}

// Verilator's messages worth showing: its %Error lines (file:line: text) and what follows each.
std::string verilator_errors(const std::string& log) {
    std::istringstream in(log);
    std::string line;
    std::string out;
    int shown = 0;
    while (std::getline(in, line) && shown < 20) {
        if (line.rfind("%Error", 0) == 0 || (!out.empty() && line.rfind(" ", 0) == 0)) {
            out += "\n  " + line;
            ++shown;
        }
    }
    return out.empty() ? "\n" + log : out;
}

void verilate(const PluginSpec& spec, const fs::path& dir) {
    write_text(dir / "observed.vlt", public_nets_config(spec));
    std::string cmd = std::string(CNC_VERILATOR_BIN) +
                      " --cc -O3 --x-assign fast --x-initial fast --noassert -Wno-fatal -Wno-lint -Wno-style" +
                      " --prefix " + kPrefix + " --top-module " + quoted(spec.top_module) + " -Mdir " +
                      quoted((dir / "obj").string()) + " -I" + quoted(fs::path(spec.sources.front()).parent_path().string());
    for (const auto& [name, value] : spec.parameters) cmd += " " + quoted("-G" + name + "=" + value);
    cmd += " " + quoted((dir / "observed.vlt").string());
    for (const std::string& src : spec.sources) cmd += " " + quoted(src);
    const fs::path log = dir / "verilator.log";
    if (!run(cmd, log)) {
        throw BadInput(spec.where, "Verilator could not build module " + spec.top_module + ":" +
                                       verilator_errors(read_text(log)));
    }
}

// The design and the shim are compiled as one translation unit with symbols hidden: Verilator's many small
// functions are then inlined into the clock loop (a shared library's exported functions are not).
std::string cxx_flags() {
    const std::string inc = std::string(CNC_VERILATOR_ROOT) + "/include";
    return std::string(CNC_RTL_CXX) +
           " -std=c++17 -O3 -fPIC -fvisibility=hidden -fno-semantic-interposition -w -pthread -I" + quoted(inc) +
           " -I" + quoted(inc + "/vltstd");
}

void compile_step(const std::string& what, const std::string& cmd, const fs::path& log) {
    if (!run(cmd, log)) {
        throw std::runtime_error("compiling " + what + " failed (" + log.string() + "):\n" +
                                 read_text(log).substr(0, 4000));
    }
}

// Verilator's run-time library, compiled once per Verilator and compiler into the cache (most of a plug-in's
// build time otherwise).
fs::path runtime_library() {
    Fnv f;
    f.add(CNC_VERILATOR_ROOT);
    f.add(cxx_flags());
    std::ostringstream hex;
    hex << "runtime-" << std::hex << f.h;
    const fs::path dir = fs::path(rtl_cache_dir()) / hex.str();
    const fs::path lib = dir / "verilated.a";
    if (fs::is_regular_file(lib)) return lib;
    const fs::path tmp = dir.string() + ".tmp" + std::to_string(getpid());
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    const std::string inc = std::string(CNC_VERILATOR_ROOT) + "/include";
    for (const char* unit : {"verilated", "verilated_threads"}) {
        compile_step(std::string("Verilator's ") + unit + ".cpp",
                     cxx_flags() + " -c " + quoted(inc + "/" + unit + ".cpp") + " -o " +
                         quoted((tmp / (std::string(unit) + ".o")).string()),
                     tmp / "compile.log");
    }
    compile_step("Verilator's run-time library",
                 "ar rcs " + quoted((tmp / "verilated.a").string()) + " " + quoted((tmp / "verilated.o").string()) +
                     " " + quoted((tmp / "verilated_threads.o").string()),
                 tmp / "ar.log");
    std::error_code ec;
    fs::rename(tmp, dir, ec);
    if (ec) fs::remove_all(tmp);  // another run put it there first
    return lib;
}

// Verilator's C++ of the design, file by file in name order.
std::vector<fs::path> generated_sources(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "obj")) {
        if (e.path().extension() == ".cpp") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

void compile(const PluginSpec& spec, const fs::path& dir, const std::vector<bool>& present,
             const std::vector<bool>& inputs_present, bool rising_only) {
    write_text(dir / "shim.cpp", shim_source(spec, kPrefix, present, inputs_present, rising_only));
    std::string unit;
    for (const fs::path& f : generated_sources(dir)) unit += "#include \"obj/" + f.filename().string() + "\"\n";
    unit += "#include \"shim.cpp\"\n";
    write_text(dir / "unit.cpp", unit);
    const fs::path runtime = runtime_library();
    compile_step("the verilated " + spec.top_module,
                 cxx_flags() + " -shared -I" + quoted((dir / "obj").string()) + " -I" + quoted(CNC_MODELS_DIR) + " " +
                     quoted((dir / "unit.cpp").string()) + " " + quoted(runtime.string()) + " -o " +
                     quoted((dir / "model.so").string()),
                 dir / "compile.log");
}

std::vector<bool> observed_in(const PluginSpec& spec, const std::string& root_header) {
    std::vector<bool> present;
    for (const ObservedNet& n : spec.observed) {
        present.push_back(root_header.find(" " + root_member(spec.top_module, n) + ";") != std::string::npos);
    }
    return present;
}

// What the shim and the loop need to know of the verilated design in `dir`: its observed nets, and whether it reacts
// to the rising edge alone.
void read_design(const PluginSpec& spec, const fs::path& dir, BuiltPlugin& built) {
    const std::string root_header = read_text(dir / "obj" / (std::string(kPrefix) + "___024root.h"));
    built.observed_present = observed_in(spec, root_header);
    std::string sources;
    for (const fs::path& f : generated_sources(dir)) sources += read_text(f);
    built.rising_edge_only = rising_edge_only(root_header, sources, kPrefix, spec.clock);
}

std::vector<bool> inputs_in(const PluginSpec& spec, const std::vector<VerilatedPort>& ports) {
    std::vector<bool> present;
    for (const RtlPort& want : spec.inputs) {
        present.push_back(
            std::any_of(ports.begin(), ports.end(), [&](const VerilatedPort& p) { return p.name == want.name; }));
    }
    return present;
}

}  // namespace

std::string rtl_cache_dir() {
    if (const char* dir = std::getenv("CNCSIM_RTL_CACHE"); dir != nullptr && *dir != '\0') return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
        return (fs::path(xdg) / "cncsim" / "rtl").string();
    }
    const char* home = std::getenv("HOME");
    return (fs::path(home != nullptr ? home : "/tmp") / ".cache" / "cncsim" / "rtl").string();
}

BuiltPlugin build_plugin(const PluginSpec& spec) {
    if (spec.sources.empty()) throw BadInput(spec.where, "no Verilog source given");
    const fs::path entry = fs::path(rtl_cache_dir()) / cache_key(spec);
    BuiltPlugin built;
    if (fs::is_regular_file(entry / "model.so")) {
        built.library = (entry / "model.so").string();
        read_design(spec, entry, built);
        built.from_cache = true;
        return built;
    }
    // Built aside and renamed into place, so that runs started together never load a half-written library.
    const auto t0 = std::chrono::steady_clock::now();
    fs::create_directories(entry.parent_path());
    const fs::path dir = entry.string() + ".tmp" + std::to_string(getpid());
    fs::remove_all(dir);
    fs::create_directories(dir);
    try {
        verilate(spec, dir);
        const std::vector<VerilatedPort> ports =
            parse_verilated_ports(read_text(dir / "obj" / (std::string(kPrefix) + ".h")));
        check_ports(spec, ports);
        read_design(spec, dir, built);
        compile(spec, dir, built.observed_present, inputs_in(spec, ports), built.rising_edge_only);
    } catch (...) {
        fs::remove_all(dir);
        throw;
    }
    std::error_code ec;
    fs::rename(dir, entry, ec);
    if (ec) fs::remove_all(dir);  // another run put the same plug-in there first
    built.library = (entry / "model.so").string();
    built.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return built;
}

}  // namespace cnc::rtl
