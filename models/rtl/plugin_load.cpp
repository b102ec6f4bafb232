#include "rtl/plugin_load.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace cnc::rtl {

std::unique_ptr<RtlModel> load_model(const BuiltPlugin& plugin) {
    void* handle = dlopen(plugin.library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) throw std::runtime_error("cannot load " + plugin.library + ": " + dlerror());
    auto abi = reinterpret_cast<CncRtlAbi>(dlsym(handle, "cncsim_rtl_abi"));
    auto create = reinterpret_cast<CncRtlCreate>(dlsym(handle, "cncsim_rtl_create"));
    if (abi == nullptr || create == nullptr || abi() != kAbiVersion) {
        throw std::runtime_error(plugin.library + " is not a cncsim RTL plug-in of interface version " +
                                 std::to_string(kAbiVersion));
    }
    return std::unique_ptr<RtlModel>(create());
}

}  // namespace cnc::rtl
