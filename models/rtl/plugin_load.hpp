// Loads a built plug-in and creates its model.
#pragma once
#include <memory>

#include "rtl/plugin_build.hpp"
#include "rtl/rtl_model.hpp"

namespace cnc::rtl {

// A new instance of the plug-in's design, out of reset only once its user clocks it with reset asserted. The
// library stays loaded for the process's lifetime (a model may outlive any handle to it).
[[nodiscard]] std::unique_ptr<RtlModel> load_model(const BuiltPlugin& plugin);

}  // namespace cnc::rtl
