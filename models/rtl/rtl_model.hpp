// The interface between cncsim and a verilated top compiled into a plug-in (plugin_build.hpp writes the plug-in's
// side). Ports and observed nets are addressed by their index in the PluginSpec the plug-in was built from; values
// are the nets' bits, zero-extended to 64.
#pragma once
#include <cstdint>

namespace cnc::rtl {

// Bumped whenever this interface changes: a cached plug-in of another version is rebuilt.
constexpr int kAbiVersion = 2;

class RtlModel {
public:
    virtual ~RtlModel() = default;
    // The input's level from the next rising clock edge on (inputs are sampled there, as by a flip-flop).
    virtual void set_input(int input, std::uint64_t value) = 0;
    // Runs up to max_cycles rising edges of the clock and stops after the first one that changed a watched value
    // (an output or an observed net). Returns the number of edges run.
    virtual std::uint64_t run(std::uint64_t max_cycles) = 0;
    // The last edge of the last run() changed none of the design's state (and no input was set since): with the
    // inputs held, every later edge leaves it as it is, so a caller may skip them.
    [[nodiscard]] virtual bool settled() const = 0;
    // A watched value after the last edge run: the outputs first, then the observed nets present in the design.
    [[nodiscard]] virtual std::uint64_t value(int watched) const = 0;
};

}  // namespace cnc::rtl

// What a plug-in exports, with C linkage so that dlsym finds them.
extern "C" {
using CncRtlCreate = cnc::rtl::RtlModel* (*)();
using CncRtlAbi = int (*)();
}
