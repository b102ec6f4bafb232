#include "init_cmd.hpp"

#include <filesystem>

#include "common/bad_input.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"
#include "scenario/starter_files.hpp"

namespace cnc::sim {

int cmd_init(const std::string& dir, std::ostream& out) {
    namespace fs = std::filesystem;
    const std::vector<StarterFile> files = starter_files(scenario_keys());
    check_output_dir(dir, "init");
    for (const StarterFile& f : files) {
        const fs::path path = fs::path(dir) / f.name;
        std::error_code ec;
        if (fs::exists(fs::symlink_status(path, ec))) {
            throw BadInput(path.string(),
                           "exists: cncsim init overwrites no file; name another folder (cncsim init DIR)");
        }
    }
    fs::create_directories(dir);
    for (const StarterFile& f : files) write_output_file((fs::path(dir) / f.name).string(), "init", f.text);
    const std::string scenario = (fs::path(dir) / files[0].name).string();
    out << "cncsim init: wrote " << scenario << " (the scenario), " << (fs::path(dir) / files[1].name).string()
        << " (its machine) and " << (fs::path(dir) / files[2].name).string() << " (its job)\n"
        << "run it: cncsim run " << scenario << "\n";
    return 0;
}

}  // namespace cnc::sim
