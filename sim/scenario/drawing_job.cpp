#include "scenario/drawing_job.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// The temporary G-code files of DXF jobs, removed when cncsim ends (every architecture reads the job from its file).
class TemporaryFiles {
public:
    ~TemporaryFiles() {
        for (const std::string& p : m_paths) {
            std::error_code ec;
            fs::remove(p, ec);
        }
    }
    std::string make(const std::string& stem) {
        const fs::path p = fs::temp_directory_path() / ("cncsim-" + std::to_string(getpid()) + "-" +
                                                        std::to_string(m_paths.size()) + "-" + stem + ".nc");
        m_paths.push_back(p.string());
        return p.string();
    }

private:
    std::vector<std::string> m_paths;
};

TemporaryFiles& temporary_files() {
    static TemporaryFiles files;
    return files;
}

}  // namespace

void write_drawing_job(Scenario& s) {
    if (s.drawing_path.empty()) return;
    std::error_code ec;
    if (!fs::is_regular_file(s.drawing_path, ec))
        throw BadInput(s.job_key, "the drawing " + s.drawing_path + " is not a file");
    const cam::Drawing drawing = cam::load_drawing(s.drawing_path, s.cam.options, s.machine);
    const cam::CamOutput out = cam::cam_output(drawing, s.cam.options.order, s.cam.options);
    const std::string path =
        s.cam.gcode_path.empty() ? temporary_files().make(fs::path(s.drawing_path).stem().string()) : s.cam.gcode_path;
    std::ofstream file(path);
    file << out.gcode;
    file.close();
    if (!file) throw BadInput(s.cam.gcode_where, "cannot write the drawing's G-code to " + path);
    s.job_path = path;
}

}  // namespace cnc::sim
