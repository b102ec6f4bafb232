// Verilates a design into a plug-in (a shared library implementing rtl_model.hpp) and caches it: the first run of a
// design pays Verilator and the C++ compiler, later runs load the library. The cache key is a hash of the sources'
// contents, the top, its parameters, the port list and this interface's version, so an edited source rebuilds.
#pragma once
#include <string>
#include <vector>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

struct BuiltPlugin {
    std::string library;                // the .so to load
    std::vector<bool> observed_present;  // per PluginSpec::observed: found in the design
    bool rising_edge_only = false;       // the design is evaluated once per clock period (rising_edge_only())
    bool from_cache = false;
    double build_s = 0.0;  // wall time of Verilator and the compiler (0 from the cache)
};

// The folder of cached plug-ins: $CNCSIM_RTL_CACHE, else $XDG_CACHE_HOME/cncsim/rtl, else ~/.cache/cncsim/rtl.
[[nodiscard]] std::string rtl_cache_dir();

// Builds the plug-in (or finds it in the cache). BadInput naming spec.where for a source that cannot be read, a
// Verilator error (its own file:line messages), a port of the list missing from the top or of another width, or
// an input of the top that cncsim does not drive.
[[nodiscard]] BuiltPlugin build_plugin(const PluginSpec& spec);

}  // namespace cnc::rtl
