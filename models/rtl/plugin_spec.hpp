// What a verilated plug-in is built from: the Verilog, its top and parameters, and the port list the simulation
// drives and reads. Pure data; plugin_build.hpp turns it into a loadable model.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace cnc::rtl {

struct RtlPort {
    std::string name;
    int width = 1;  // bits
    // An input the design may lack (a user's top written before an option added it): driven if present.
    bool optional = false;
};

// A net inside the design read after each clock edge (for a model's records; never driven).
struct ObservedNet {
    std::string module;  // the module that declares it, as in the Verilog
    std::string path;    // its instance path from the top ("step_gen_inst.state"; a net of the top: "pkt_valid")
    std::string var;     // its name in that module
};

// The Verilog a scenario asks for: ours (no top file) or the user's, and the top parameters it sets.
struct Design {
    std::string top_file;              // empty: the architecture's own Verilog
    std::vector<std::string> sources;  // the user's other .v files
    std::vector<std::pair<std::string, std::string>> parameters;  // top parameter overrides, Verilog literals
    std::string where;                                            // the scenario key, for messages
};

struct PluginSpec {
    std::string top_module;
    std::vector<std::string> sources;                           // .v files; the first one's folder is on the include path
    std::vector<std::pair<std::string, std::string>> parameters;  // top parameter overrides, Verilog literals
    std::string clock;                                          // the rising-edge clock input the model runs
    std::vector<RtlPort> inputs;                                // set by the simulation, besides the clock
    std::vector<RtlPort> outputs;
    std::vector<ObservedNet> observed;  // those absent from the design are left out (PluginInfo::observed)
    std::string where;                  // the scenario key that named the design, for messages
};

// The parameters a Verilog text declares, each with its own `parameter` keyword (parameter [7:0] NAME = ...): those
// the simulation may set with Verilator's -G (which refuses a name the top does not declare).
[[nodiscard]] std::vector<std::string> declared_parameters(const std::string& verilog_text);

}  // namespace cnc::rtl
