// cncsim compare on the seed jobs (scenarios/compare): what the physics of each architecture says must hold, with
// the bound derived in each test from the seed, a data sheet or the geometry, never from a run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/command_output.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kCompare = std::string(CNC_SOURCE_DIR) + "/scenarios/compare/";

constexpr double kStepsPerMm = 160.0;             // seed 000 machine: 200 full steps x 32 / (20 teeth x 2 mm)
constexpr double kStepUm = 1000.0 / kStepsPerMm;  // 6.25 um
constexpr double kFpgaClockNs = 20.0;             // fpga.clock_hz 50 MHz (seed 000 CLOCK_50)
// A carriage that moves one microstep per step: where the tool is follows from the step counts alone.
const std::string kIdealMechanics = " --set mechanics.model=ideal";

struct Comparison {
    nlohmann::json columns;  // compare --format json
    fs::path out;            // compare --out

    const nlohmann::json& column(const std::string& arch) const {
        for (const auto& c : columns) {
            if (c.at("architecture") == arch) return c;
        }
        throw std::runtime_error("no column " + arch);
    }
    double metric(const std::string& arch, const char* key) const {
        return column(arch).at("metrics").at(key).get<double>();
    }
    // The dead time of every gap, between moves and inside them, ms, as the plot data has it
    // (data/<arch>/dead_time.dat).
    std::vector<double> gaps_ms(const std::string& arch) const {
        std::ifstream in(out / "data" / arch / "dead_time.dat");
        std::vector<double> out_ms;
        for (std::string line; std::getline(in, line);) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream f(line);
            double gap = 0, move = 0, inside = 0, total = 0;
            f >> gap >> move >> inside >> total;
            out_ms.push_back(total);
        }
        return out_ms;
    }
};

// Each test its own output folder, named after it.
Comparison compare(const std::string& scenario, const std::string& archs) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path out = fs::temp_directory_path() / (std::string("cncsim-") + info->test_suite_name() + "." +
                                                      info->name() + "-" + std::to_string(getpid()));
    fs::remove_all(out);
    const std::string cmd = std::string(CNCSIM_EXE) + " compare " + scenario + " --arch " + archs + " --out " +
                            out.string() + " --format json 2>/dev/null";
    return {nlohmann::json::parse(cnc::test::command_output(cmd)), out};
}

struct CleanUp : ::testing::Test {
    std::vector<fs::path> outs;
    Comparison run(const std::string& scenario, const std::string& archs) {
        Comparison c = compare(scenario, archs);
        outs.push_back(c.out);
        return c;
    }
    void TearDown() override {
        for (const fs::path& p : outs) fs::remove_all(p);
    }
};

using ComparePhysics = CleanUp;

}  // namespace

// step_gen counts whole 50 MHz clocks for every period: an edge can be off the ideal grid of its run by at most the
// clock it is quantised to, on every job.
TEST_F(ComparePhysics, FpgaUartTieIsWithinOneFpgaClockOnEverySeedJob) {
    for (const char* job : {"six_segment", "square_20mm", "diagonal_45", "circle_r10", "fast_80mm_s"}) {
        const Comparison c = run(kCompare + job + ".toml", "fpga-uart");
        EXPECT_EQ(c.column("fpga-uart").at("status"), "ok") << job;
        EXPECT_LE(c.metric("fpga-uart", "metrics/pulse/tie_max_ns"), kFpgaClockNs) << job;
    }
}

// Seed 003 eqs. 5.1-5.2: 10.45 mm/s at 160 steps/mm is 1672 steps/s; OCR = 16 MHz / (2 x 1024 x 1672) - 1 = 3.673,
// truncated to 3, so a STEP every 2 x 1024 x 4 cycles: 1953.1 steps/s = 12.207 mm/s, +16.81 % (the seed's 12.21).
TEST_F(ComparePhysics, AtmegaRateErrorOnTheSeedSpeedExampleIsTheTruncatedCompareValue) {
    const Comparison c = run(std::string(CNC_SOURCE_DIR) + "/scenarios/atmega/speed_10_45.toml", "atmega");
    const double achieved = 16e6 / (2.0 * 1024.0 * 4.0);
    const double expected_pct = (achieved / (10.45 * kStepsPerMm) - 1.0) * 100.0;
    EXPECT_NEAR(expected_pct, 16.8, 0.05);
    // This unit's resonator runs its timers (1 + offset) times fast, the offset as the run reports it.
    const double offset = c.column("atmega").at("clock").at("offset_ppm").get<double>() * 1e-6;
    const double unit_pct = (achieved * (1.0 + offset) / (10.45 * kStepsPerMm) - 1.0) * 100.0;
    EXPECT_NEAR(c.metric("atmega", "metrics/pulse/rate_error_worst_pct"), unit_pct, 0.001);
}

// Stop-and-wait (seed 000 §4.14): between two packets (two moves, or two chords of the circle) the ACK must cross the line and reach the host, and the next
// 11-byte packet must cross the line before the FPGA can step again. The CP2102 runs 115200 Bd as 24 MHz / 208 =
// 115 384.6 Bd (AN205): 11 bytes x 10 bits (8N1) = 953.3 us, the ACK's 10 bits = 86.7 us; the host's driver sees
// received bytes link.usb_latency_ms (1 ms) after a USB frame boundary at the earliest. Every gap is at least
// 2.040 ms.
TEST_F(ComparePhysics, FpgaUartDeadTimePerMoveCoversPacketAckAndUsbLatency) {
    const double bit_us = 1e6 * 208.0 / 24e6;
    const double floor_ms = (110.0 * bit_us + 10.0 * bit_us + 1000.0) / 1000.0;
    EXPECT_NEAR(floor_ms, 2.040, 0.001);
    for (const char* job : {"six_segment", "square_20mm", "circle_r10"}) {
        const Comparison c = run(kCompare + job + ".toml", "fpga-uart");
        const std::vector<double> gaps = c.gaps_ms("fpga-uart");
        ASSERT_FALSE(gaps.empty()) << job;
        for (std::size_t i = 0; i < gaps.size(); ++i) EXPECT_GE(gaps[i], floor_ms) << job << " gap " << i + 1;
    }
}

// Continuous mode (G64) crosses the joins of colinear moves at speed: the only time without a STEP between two
// moves is the step period itself, 60 / (1200 mm/min x 160 steps/mm) = 312.5 us at F1200. fpga-uart on the same
// job stops for its handshake (the 2.040 ms floor above).
TEST_F(ComparePhysics, SpiFpgaContinuousModeHasNoDeadTimeBetweenColinearMoves) {
    const Comparison c = run(std::string(CNC_SOURCE_DIR) + "/scenarios/spi-fpga/colinear_x.toml", "spi-fpga,fpga-uart");
    const double period_ms = 60.0 / (1200.0 * kStepsPerMm) * 1000.0;
    const std::vector<double> spi = c.gaps_ms("spi-fpga");
    ASSERT_EQ(spi.size(), 2U);  // three moves
    for (const double g : spi) EXPECT_LE(g, period_ms * 1.001);
    for (const double g : c.gaps_ms("fpga-uart")) EXPECT_GE(g, 2.040);
}

// With ideal mechanics (one microstep per STEP edge) every controller that counts all its steps ends the job on its
// last programmed point to the step: fpga-uart sends absolute-rounded step counts, spi-fpga lands each axis on its
// commanded count at every rest. The atmega firmware counts only X in G01 and in its arc chords (seed 003 App. A3),
// so it ends on the point only when its Y rate matches: on the square and the diagonal. On the six-segment job its
// 4132 x 3864-step diagonal runs both axes at OCR 2/2, so Y makes X's 4132 steps: 268 steps = 1.675 mm past.
TEST_F(ComparePhysics, JobEndErrorIsZeroStepsWithIdealMechanics) {
    for (const char* job : {"square_20mm", "diagonal_45"}) {
        const Comparison c = run(kCompare + job + ".toml" + kIdealMechanics, "fpga-uart,atmega,spi-fpga");
        for (const char* arch : {"fpga-uart", "atmega", "spi-fpga"}) {
            EXPECT_EQ(c.metric(arch, "metrics/path/job_end_um"), 0.0) << job << " " << arch;
        }
    }
    for (const char* job : {"six_segment", "circle_r10", "fast_80mm_s"}) {
        const Comparison c = run(kCompare + job + ".toml" + kIdealMechanics, "fpga-uart,spi-fpga");
        for (const char* arch : {"fpga-uart", "spi-fpga"}) {
            EXPECT_EQ(c.metric(arch, "metrics/path/job_end_um"), 0.0) << job << " " << arch;
        }
    }
    const Comparison six = run(kCompare + "six_segment.toml" + kIdealMechanics, "atmega");
    EXPECT_NEAR(six.metric("atmega", "metrics/path/job_end_um"), (4132 - 3864) * kStepUm, 1e-6);
}

// The orderings of contour error the controllers produce on a carriage that moves one microstep per step:
// - square (axis-parallel lines): fpga-uart and atmega step one axis while the other holds, so every tool sample is
//   on the programmed line: 0. spi-fpga blends each corner within planner.path_tolerance_mm (G64 P, 0.05 mm), so its
//   error is the blend's, above 0 and at most 50 um plus the half step the counts round to.
// - circle: fpga-uart's chords lie within host.chord_tolerance_mm (2 um) of the arc and step_gen's staircase adds at
//   most one step: <= 8.25 um. spi-fpga follows the arc as an arc but blends the rapid into it within the path
//   tolerance: above fpga-uart's bound, at most 50 um + half a step. atmega's chords count X only, so Y drifts off the
//   arc along each chord: far beyond both bounds.
TEST_F(ComparePhysics, ContourErrorOrderings) {
    const double blend_bound_um = 50.0 + kStepUm / 2.0;
    const Comparison square = run(kCompare + "square_20mm.toml" + kIdealMechanics, "fpga-uart,atmega,spi-fpga");
    EXPECT_LT(square.metric("fpga-uart", "metrics/path/contour_max_um"), 1e-6);  // 0 up to the mm -> um rounding
    EXPECT_LT(square.metric("atmega", "metrics/path/contour_max_um"), 1e-6);
    EXPECT_GT(square.metric("spi-fpga", "metrics/path/contour_max_um"), 0.0);
    EXPECT_LE(square.metric("spi-fpga", "metrics/path/contour_max_um"), blend_bound_um);

    const Comparison circle = run(kCompare + "circle_r10.toml" + kIdealMechanics, "fpga-uart,atmega,spi-fpga");
    const double chord_bound_um = 2.0 + kStepUm + 0.001;
    const double fpga = circle.metric("fpga-uart", "metrics/path/contour_max_um");
    const double spi = circle.metric("spi-fpga", "metrics/path/contour_max_um");
    const double avr = circle.metric("atmega", "metrics/path/contour_max_um");
    EXPECT_LE(fpga, chord_bound_um);
    EXPECT_GT(spi, chord_bound_um);
    EXPECT_LE(spi, blend_bound_um);
    EXPECT_GT(avr, blend_bound_um);
}

// The ideal architecture is the machine's own motion: with the dynamic carriage on the circle, no architecture
// follows the path closer (each one's controller can only add to the carriage's lag and ringing), and each one's
// row "contour error max over ideal" is its contour error max minus the ideal's.
TEST_F(ComparePhysics, NoArchitectureFollowsTheCircleCloserThanTheIdealController) {
    const Comparison c = run(kCompare + "circle_r10.toml", "ideal,fpga-uart,atmega,spi-fpga");
    const char* contour = "metrics/path/contour_max_um";
    const char* over = "metrics/path/contour_max_over_ideal_um";
    const double ideal = c.metric("ideal", contour);
    EXPECT_EQ(c.metric("ideal", over), 0.0);
    for (const char* arch : {"fpga-uart", "atmega", "spi-fpga"}) {
        EXPECT_EQ(c.column(arch).at("status"), "ok") << arch;
        EXPECT_LE(ideal, c.metric(arch, contour)) << arch;
        EXPECT_DOUBLE_EQ(c.metric(arch, over), c.metric(arch, contour) - ideal) << arch;
    }
}

// compare runs the ideal controller with every comparison for that row, and shows it as a column only when asked.
TEST_F(ComparePhysics, TheIdealControllerIsABaselineColumnOnlyWhenAsked) {
    const Comparison c = run(kCompare + "square_20mm.toml", "fpga-uart,spi-fpga");
    ASSERT_EQ(c.columns.size(), 2U);
    const double over = c.metric("spi-fpga", "metrics/path/contour_max_over_ideal_um");
    EXPECT_FALSE(fs::exists(c.out / "ideal.json"));
    EXPECT_FALSE(fs::exists(c.out / "data" / "ideal"));
    const Comparison with = run(kCompare + "square_20mm.toml", "spi-fpga,ideal");  // the same folder
    ASSERT_EQ(with.columns.size(), 2U);
    EXPECT_DOUBLE_EQ(over, with.metric("spi-fpga", "metrics/path/contour_max_um") -
                               with.metric("ideal", "metrics/path/contour_max_um"));
    EXPECT_TRUE(fs::exists(with.out / "data" / "ideal"));
}
