#include "probes/vcd_trace.hpp"

#include <filesystem>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {
std::string without_vcd_extension(const std::string& path) {
    const std::string ext = ".vcd";
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0) {
        return path.substr(0, path.size() - ext.size());
    }
    return path;
}
}  // namespace

VcdTrace::VcdTrace(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
        throw BadInput(path, "the VCD file's folder does not exist");
    }
    m_file = sc_core::sc_create_vcd_trace_file(without_vcd_extension(path).c_str());
    m_file->set_time_unit(1, sc_core::SC_PS);
}

VcdTrace::~VcdTrace() { sc_core::sc_close_vcd_trace_file(m_file); }

void VcdTrace::trace(const sc_core::sc_signal<bool>& signal) { sc_core::sc_trace(m_file, signal, signal.basename()); }

}  // namespace cnc::sim
