#include "rtl/design_sources.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace cnc::rtl {

void set_design(PluginSpec& spec, const Design& design, const std::string& own_top, const std::string& own_dir,
                const std::vector<std::string>& own_files, std::vector<std::pair<std::string, std::string>> from_keys) {
    spec.where = design.where;
    spec.parameters = std::move(from_keys);
    if (design.top_file.empty()) {
        spec.top_module = own_top;
        for (const std::string& f : own_files) spec.sources.push_back((std::filesystem::path(own_dir) / f).string());
    } else {
        spec.top_module = std::filesystem::path(design.top_file).stem().string();
        spec.sources.push_back(design.top_file);
        spec.sources.insert(spec.sources.end(), design.sources.begin(), design.sources.end());
        std::ifstream in(design.top_file);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::vector<std::string> declared = declared_parameters(text);
        spec.parameters.erase(
            std::remove_if(
                spec.parameters.begin(), spec.parameters.end(),
                [&](const auto& p) { return std::find(declared.begin(), declared.end(), p.first) == declared.end(); }),
            spec.parameters.end());
    }
    spec.parameters.insert(spec.parameters.end(), design.parameters.begin(), design.parameters.end());
}

}  // namespace cnc::rtl
