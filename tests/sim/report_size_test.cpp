// Reports that scale: the default JSON report of a long job stays under 5 MB. Two generated jobs, each run by
// cncsim in its own process (one SystemC elaboration per process) and its report file measured: 250 s of circles
// on spi-fpga (every 1 ms servo period changes both rate words) and a 40,000-line laser raster on fpga-uart.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/test_path.hpp"

namespace {

constexpr std::uintmax_t kReportBoundBytes = 5'000'000;

struct Report {
    std::uintmax_t bytes = 0;
    nlohmann::json json;
};

// Writes the job and a scenario for the seed 000 machine (160 steps/mm), runs it and reads the report back.
Report run_generated(const std::string& name, const std::string& architecture, const std::string& gcode) {
    const std::string dir = cnc::test::test_path("");
    std::ofstream(dir + name + ".nc") << gcode;
    std::ofstream(dir + name + ".toml") << "[scenario]\narchitecture = \"" << architecture << "\"\njob = \"" << name
                                        << ".nc\"\nmax_sim_s = 10000\n"
                                        << "[machine.x]\nmicrosteps = 32\npulley_teeth = 20\nbelt_pitch_mm = 2.0\n"
                                        << "[machine.y]\nmicrosteps = 32\npulley_teeth = 20\nbelt_pitch_mm = 2.0\n";
    const std::string report = dir + name + ".json";
    const std::string cmd = std::string(CNCSIM) + " run " + dir + name + ".toml --report " + report + " > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    Report r;
    r.bytes = std::filesystem::file_size(report);
    std::ifstream in(report);
    r.json = nlohmann::json::parse(in);
    std::cout << name << ": default report " << r.bytes << " bytes\n";
    return r;
}

// 80 full circles of r 10 mm at F1200: 80 x 20 pi mm at 20 mm/s = 251.3 s of motion.
std::string circles_job() {
    std::string g = "G21 G90\nG0 X10 Y0\nM3 S255\n";
    for (int i = 0; i < 80; ++i) g += "G2 X10 Y0 I-10 J0 F1200\n";
    return g + "M5\nM30\n";
}

// A laser raster as an image-to-G-code tool writes it: 400 rows, each a G0 to its start and 99 G1 pieces of
// 0.05 .. 0.4 mm (one per run of equal pixels) at F3000, alternating in direction, Y wandering by a few um.
std::string raster_job() {
    std::ostringstream g;
    g << "G21 G90\nM3 S255\n";
    char line[64];
    for (int row = 0; row < 400; ++row) {
        const double y_mm = 1.0 + 0.1 * row;
        double x_mm = row % 2 == 0 ? 1.0 : 40.0;
        std::snprintf(line, sizeof line, "G0 X%.3f Y%.3f\n", x_mm, y_mm);
        g << line;
        for (int k = 0; k < 99; ++k) {
            const double piece_mm = 0.05 + 0.35 * ((row * 99 + k) * 37 % 100) / 100.0;
            x_mm += row % 2 == 0 ? piece_mm : -piece_mm;
            std::snprintf(line, sizeof line, "G1 X%.3f Y%.3f F3000\n", x_mm, y_mm + 0.005 * (k % 3 - 1));
            g << line;
        }
    }
    g << "M5\nM30\n";
    return g.str();
}

TEST(ReportSize, SpiFpga250sOfCirclesStaysUnder5MB) {
    const Report r = run_generated("report_size_circles", "spi-fpga", circles_job());
    ASSERT_TRUE(r.json.at("ok").get<bool>());
    EXPECT_GT(r.json.at("metrics").at("job").at("job_time_s").get<double>(), 251.3);
    EXPECT_GT(r.json.at("spi-fpga").at("servo").at("periods").get<int>(), 251'300);  // one per ms
    EXPECT_FALSE(r.json.at("spi-fpga").contains("rate_log"));
    EXPECT_LT(r.bytes, kReportBoundBytes);
}

TEST(ReportSize, FpgaUart40000LineLaserRasterStaysUnder5MB) {
    const Report r = run_generated("report_size_raster", "fpga-uart", raster_job());
    ASSERT_TRUE(r.json.at("ok").get<bool>());
    EXPECT_EQ(r.json.at("metrics").at("moves").at("index").size(), 40'000U);  // 400 x (G0 + 99 G1)
    EXPECT_LT(r.bytes, kReportBoundBytes);
}

}  // namespace
