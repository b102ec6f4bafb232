#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "architectures/fpga_uart/fpga_uart_settings.hpp"
#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"
#include "support/test_path.hpp"

namespace {

// A scenario file in the test's own folder.
std::string write_scenario(const std::string& name, const std::string& text) {
    const std::string path = cnc::test::test_path(name + ".toml");
    std::ofstream(path) << text;
    return path;
}

std::string load_error(const std::string& path, const std::vector<std::string>& sets = {}) {
    try {
        cnc::sim::load_scenario(path, sets);
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

const char* kJob = "[scenario]\njob = \"square.nc\"\n";

}  // namespace

TEST(Scenario, DefaultsAreTheSeed000ReferenceMachine) {
    const auto s = cnc::sim::load_scenario(write_scenario("defaults", kJob), {});
    EXPECT_EQ(s.architecture, "fpga-uart");
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 160.0);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 160.0);
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().serial.link.requested_baud, 115'200U);
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().fpga.uart_full_bit_cycles, 434U);
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().fpga.uart_half_bit_cycles, 217U);
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().fpga.watchdog_cycles, 5'000'000U);
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().serial.sender.ack_timeout_ps, 10 * cnc::kPsPerSec);
    EXPECT_EQ(s.job_format, cnc::sim::JobFormat::GCode);
    EXPECT_EQ(s.job_path, cnc::test::test_path("square.nc"));  // relative to the scenario's folder
}

TEST(Scenario, SetOverridesTypedValuesAndBareStrings) {
    const auto s = cnc::sim::load_scenario(
        write_scenario("set", kJob),
        {"link.baud=57600", "machine.x.microsteps=16", "host.on_timeout=continue", "scenario.job=other.steps"});
    EXPECT_EQ(s.settings<cnc::sim::FpgaUartSettings>().serial.link.requested_baud, 57'600U);
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 80.0);
    EXPECT_TRUE(s.settings<cnc::sim::FpgaUartSettings>().serial.sender.continue_on_timeout);
    EXPECT_EQ(s.job_format, cnc::sim::JobFormat::Steps);
}

TEST(Scenario, StepsPerMmAloneReplacesTheTransmissionAndKeepsTheMicrostepMode) {
    const auto s = cnc::sim::load_scenario(
        write_scenario("spm", std::string(kJob) + "[machine.x]\nsteps_per_mm = 100\nmicrosteps = 16\n"), {});
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 100.0);
    EXPECT_EQ(s.machine.x.microsteps, 16);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 160.0);
}

TEST(Scenario, StepsPerMmWithoutMicrostepsIsRefusedUnderTheDynamicMotor) {
    // grbl's $100 = 80 on a 1/16 belt machine: alone it would leave the DRV8825 at the default 1/32, and the
    // motor at 80 / 32 = 2.5 full steps per mm instead of 80 / 16 = 5.
    const std::string path = write_scenario("spm_alone", std::string(kJob) + "[machine.x]\nsteps_per_mm = 80\n");
    const std::string err = load_error(path);
    EXPECT_NE(err.find(path + ":4: machine.x.steps_per_mm: 80 steps/mm without machine.x.microsteps"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("2.5 at the default 1/32"), std::string::npos) << err;
    // 1.8 deg, GT2 20T: 200 full steps per 40 mm = 5 full steps/mm, so 80 steps/mm is 1/16.
    EXPECT_NE(err.find("16 gives 80 steps/mm"), std::string::npos) << err;
    EXPECT_NE(load_error(path, {"machine.y.steps_per_mm=80", "machine.x.microsteps=16"}).find("machine.y.microsteps"),
              std::string::npos);
}

TEST(Scenario, StepsPerMmWithMicrostepsFixesTheFullStepsPerMm) {
    const auto s = cnc::sim::load_scenario(
        write_scenario("spm_micro", std::string(kJob) + "[machine.x]\nsteps_per_mm = 80\nmicrosteps = 16\n"), {});
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm() / s.machine.x.microsteps, 5.0);
    // What the motor turns per mm: 1 / 5 mm per full step, 1.8 deg each, is 200 full steps per 40 mm.
    EXPECT_DOUBLE_EQ(s.machine.x.travel_per_motor_rev_mm(), 40.0);
}

TEST(Scenario, StepsPerMmAloneIsTakenWhereNoMotorIsModelled) {
    // The ideal carriage moves one microstep per step whatever the mode; Z has no motor model at all.
    const std::string path = write_scenario("spm_ideal", std::string(kJob) + "[machine.x]\nsteps_per_mm = 80\n");
    EXPECT_EQ(load_error(path, {"mechanics.model=ideal"}), "");
    EXPECT_EQ(load_error(write_scenario("spm_z", std::string(kJob) + "[machine.z]\nsteps_per_mm = 400\n")), "");
}

TEST(Scenario, StepsPerMmEqualToTheTransmissionsIsAccepted) {
    // Leadscrew 8 mm, 1/16: 3200 / 8 = 400 steps/mm; a difference of 1e-12 relative is rounding.
    const auto s = cnc::sim::load_scenario(
        write_scenario("spm_equal", std::string(kJob) + "[machine.y]\ntransmission = \"leadscrew\"\n"
                                                        "microsteps = 16\nsteps_per_mm = 400.0000000004\n"),
        {});
    EXPECT_NEAR(s.machine.y.steps_per_mm(), 400.0, 1e-9);
}

TEST(Scenario, StepsPerMmContradictingTheTransmissionNamesBothKeysAndValues) {
    const std::string path =
        write_scenario("spm_conflict", std::string(kJob) + "[machine.x]\npulley_teeth = 20\nsteps_per_mm = 100\n");
    const std::string err = load_error(path);
    EXPECT_NE(err.find(path + ":5: machine.x.steps_per_mm: 100 differs from the 160 steps/mm"), std::string::npos)
        << err;
    EXPECT_NE(err.find("machine.x.pulley_teeth"), std::string::npos) << err;
    // 1e-6 relative is more than rounding: refused
    EXPECT_NE(
        load_error(write_scenario("spm_close", kJob), {"machine.x.gear_ratio=1", "machine.x.steps_per_mm=160.00016"})
            .find("machine.x.steps_per_mm"),
        std::string::npos);
}

TEST(Scenario, StartPositionOutsideTheTravelNamesTheStartKey) {
    const std::string path =
        write_scenario("start", "[scenario]\njob = \"square.nc\"\nstart_x_mm = 12\n[machine.x]\ntravel_mm = 10\n");
    const std::string err = load_error(path);
    EXPECT_NE(err.find(path + ":3: scenario.start_x_mm: X 12 mm is past machine.x.travel_mm = 10"), std::string::npos)
        << err;
    EXPECT_EQ(load_error(path, {"machine.soft_limits=false"}), "");
}

TEST(Scenario, UnknownKeyNamesFileLineKeyAndTheAllowedKeys) {
    const std::string path =
        write_scenario("unknown", std::string(kJob) + "\n[link]\nbaud = 115200\nusb_latncy_ms = 2.0\n");
    const std::string err = load_error(path);
    EXPECT_NE(err.find(path + ":6: link.usb_latncy_ms"), std::string::npos) << err;
    EXPECT_NE(err.find("unknown key"), std::string::npos) << err;
    EXPECT_NE(err.find("usb_latency_ms"), std::string::npos) << err;
}

TEST(Scenario, UnknownSectionIsRejected) {
    const std::string err = load_error(write_scenario("section", std::string(kJob) + "[lnik]\nbaud = 1\n"));
    EXPECT_NE(err.find("lnik"), std::string::npos) << err;
    EXPECT_NE(err.find("unknown key (allowed at the top level: scenario, machine"), std::string::npos) << err;
}

TEST(Scenario, WrongTypeAndRangeAndChoice) {
    EXPECT_NE(load_error(write_scenario("type", std::string(kJob) + "[machine.x]\nmicrosteps = \"32\"\n"))
                  .find("machine.x.microsteps: expected an integer, got string"),
              std::string::npos);
    EXPECT_NE(load_error(write_scenario("range", std::string(kJob) + "[link]\nbaud = 5\n"))
                  .find("link.baud: 5 is out of range (allowed 300 .. 921600)"),
              std::string::npos);
    EXPECT_NE(load_error(write_scenario("choice", std::string(kJob) + "[host]\non_timeout = \"retry\"\n"))
                  .find("'retry' is not allowed (allowed: abort | continue)"),
              std::string::npos);
}

TEST(Scenario, ImpossibleMachineAndMissingJob) {
    const std::string err = load_error(write_scenario("machine", std::string(kJob) + "[machine.y]\nmicrosteps = 12\n"));
    EXPECT_NE(err.find("machine.y.microsteps"), std::string::npos) << err;
    EXPECT_NE(err.find("1, 2, 4, 8, 16"), std::string::npos) << err;
    EXPECT_NE(load_error(write_scenario("nojob", "[scenario]\nname = \"x\"\n")).find("scenario.job: missing"),
              std::string::npos);
}

TEST(Scenario, FpgaValuesTheRtlCannotHoldNameTheScenarioKey) {
    const std::string err = load_error(write_scenario("fpga", std::string(kJob) + "[fpga]\nuart_baud = 9600\n"));
    EXPECT_NE(err.find("fpga.uart_baud"), std::string::npos) << err;
    EXPECT_NE(err.find("2..512"), std::string::npos) << err;
    EXPECT_NE(
        load_error(write_scenario("clock", std::string(kJob) + "[fpga]\nclock_hz = 48000000\n")).find("fpga.clock_hz"),
        std::string::npos);
}

TEST(Scenario, TomlSyntaxErrorNamesTheLine) {
    const std::string path = write_scenario("syntax", "[scenario]\njob = \"a.nc\"\nseed = = 3\n");
    EXPECT_NE(load_error(path).find(path + ":3"), std::string::npos) << load_error(path);
}

// The scenario reference (docs/scenario-reference.md) is generated by `cncsim keys`; this keeps the two from
// drifting apart.
TEST(Scenario, KeyReferenceMatchesTheLoader) {
    std::ifstream readme(std::string(CNC_SOURCE_DIR) + "/docs/scenario-reference.md");
    std::stringstream text;
    text << readme.rdbuf();
    const std::string all = text.str();
    const std::string begin = "<!-- keys:begin -->\n";
    const std::string end = "<!-- keys:end -->";
    const auto b = all.find(begin);
    const auto e = all.find(end);
    ASSERT_NE(b, std::string::npos);
    ASSERT_NE(e, std::string::npos);
    EXPECT_EQ(all.substr(b + begin.size(), e - b - begin.size()), cnc::sim::keys_markdown(cnc::sim::scenario_keys()))
        << "regenerate with: ./build/sim/cncsim keys";
}
