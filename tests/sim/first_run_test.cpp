// A first run: a job without a scenario on the default machine or a machine file, how `run` tells a job from a
// scenario, the machine file a scenario names or `motor-curve --machine` reads alone, `keys PREFIX`, and the files
// `init` writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "scenario/key_listing.hpp"
#include "scenario/scenario.hpp"
#include "scenario/starter_files.hpp"
#include "support/bad_input_message.hpp"
#include "support/test_path.hpp"

namespace {

using cnc::sim::InputKind;
using cnc::test::bad_input_message;

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = cnc::test::test_path(name);
    std::ofstream(path) << text;
    return path;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A belt axis of the seed 000 machine (1.8 deg, GT2 20T) at 1/16: 200 x 16 / (20 x 2 mm) = 80 steps/mm.
const char* kMachine = "[machine.x]\nmicrosteps = 16\n\n[mechanics.x]\ncarriage_mass_kg = 2.0\n";

}  // namespace

TEST(InputKind, TheExtensionDecidesWhenItIsKnown) {
    // The content does not matter then: a .toml of G-code is a scenario (its parse error says so), a .nc of TOML a job.
    EXPECT_EQ(cnc::sim::input_kind(write_file("a.toml", "G0 X1\n")), InputKind::Scenario);
    EXPECT_EQ(cnc::sim::input_kind(write_file("a.nc", "[scenario]\n")), InputKind::Job);
    for (const char* name : {"b.ngc", "b.gcode", "b.GCODE", "b.tap", "b.txt", "b.steps"}) {
        EXPECT_EQ(cnc::sim::input_kind(write_file(name, "[scenario]\n")), InputKind::Job) << name;
    }
}

TEST(InputKind, OtherwiseTheFirstLineThatIsNoTomlCommentDecides) {
    EXPECT_EQ(cnc::sim::input_kind(write_file("table", "# a scenario\n\n[scenario]\njob = \"a.nc\"\n")),
              InputKind::Scenario);
    EXPECT_EQ(cnc::sim::input_kind(write_file("key", "\n  scenario.job = \"a.nc\"\n")), InputKind::Scenario);
    EXPECT_EQ(cnc::sim::input_kind(write_file("gcode", "; a job\nG0 X1 Y1\n")), InputKind::Job);
    EXPECT_EQ(cnc::sim::input_kind(write_file("gcode2", "(a job)\nG1 X1 F100\n")), InputKind::Job);
    EXPECT_EQ(cnc::sim::input_kind(write_file("percent", "%\nG1 X1 F100\n%\n")), InputKind::Job);
    // Nothing to read: a scenario, whose loader names the file as one.
    EXPECT_EQ(cnc::sim::input_kind(cnc::test::test_path("missing")), InputKind::Scenario);
}

TEST(JobRun, RunsOnTheDefaultMachineThroughTheDefaultArchitecture) {
    const std::string job = write_file("square.nc", "G1 X10 F600\n");
    const cnc::sim::Scenario s = cnc::sim::load_job_run({job, "", ""}, {});
    EXPECT_EQ(s.architecture, "fpga-uart");
    EXPECT_EQ(s.name, "square");
    EXPECT_EQ(s.job_path, job);
    // The seed 000 machine: 200 full steps x 32 / (20 teeth x 2 mm) = 160 steps/mm.
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 160.0);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 160.0);
}

TEST(JobRun, TakesTheMachineFileTheArchitectureAndOverrides) {
    const std::string job = write_file("square.nc", "G1 X10 F600\n");
    const std::string machine = write_file("machine.toml", kMachine);
    const cnc::sim::Scenario s =
        cnc::sim::load_job_run({job, machine, "spi-fpga"}, {"machine.y.microsteps=8", "scenario.name=mine"});
    EXPECT_EQ(s.architecture, "spi-fpga");
    EXPECT_EQ(s.name, "mine");
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 80.0);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 40.0);  // 200 x 8 / 40 mm
    EXPECT_DOUBLE_EQ(s.mechanics.x.carriage_mass_kg, 2.0);
}

TEST(JobRun, BadInputNamesTheFileAndKey) {
    const std::string job = write_file("square.nc", "G1 X10 F600\n");
    const std::string bad_key = write_file("bad_key.toml", "[machine.x]\nmicrosteps = 16\nmicrostep = 8\n");
    EXPECT_TRUE(contains(bad_input_message([&] {
                             cnc::sim::load_job_run({job, bad_key, ""}, {});
                         }),
                         bad_key + ":3: machine.x.microstep: unknown key (allowed in [machine.x]:"));
    const std::string bad_value = write_file("bad_value.toml", "[machine.x]\nmicrosteps = 3\n");
    const std::string value_err = bad_input_message([&] { cnc::sim::load_job_run({job, bad_value, ""}, {}); });
    EXPECT_TRUE(contains(value_err, bad_value + ":") && contains(value_err, "machine.x.microsteps")) << value_err;
    const std::string link = write_file("link.toml", "[machine.x]\nmicrosteps = 16\n[link]\nbaud = 57600\n");
    EXPECT_TRUE(contains(bad_input_message([&] {
                             cnc::sim::load_job_run({job, link, ""}, {});
                         }),
                         link + ":3: link: not a machine table"));
    EXPECT_TRUE(contains(bad_input_message([&] {
                             cnc::sim::load_job_run({job + "x", "", ""}, {});
                         }),
                         job + "x: no such job file"));
    EXPECT_TRUE(contains(bad_input_message([&] {
                             cnc::sim::load_job_run({job, job + ".toml", ""}, {});
                         }),
                         "--machine " + job + ".toml: no such machine file"));
    EXPECT_TRUE(contains(bad_input_message([&] {
                             cnc::sim::load_job_run({job, "", "lathe-sync"}, {});
                         }),
                         "--arch lathe-sync: lathe-sync runs no job"));
}

// `motor-curve --machine`: the machine file alone, no job read or needed, the overrides on top.
TEST(MachineOnly, ReadsTheMachineFileWithoutAJob) {
    const std::string machine = write_file("machine.toml", kMachine);
    const cnc::sim::Scenario s = cnc::sim::load_machine(machine, {"machine.y.microsteps=8"});
    EXPECT_TRUE(s.job_path.empty());
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 80.0);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 40.0);  // 200 x 8 / 40 mm
    EXPECT_DOUBLE_EQ(s.mechanics.x.carriage_mass_kg, 2.0);
    const std::string bad_key = write_file("bad_key.toml", "[machine.x]\nmicrostep = 8\n");
    EXPECT_TRUE(contains(bad_input_message([&] { cnc::sim::load_machine(bad_key, {}); }),
                         bad_key + ":2: machine.x.microstep: unknown key"));
    EXPECT_TRUE(contains(bad_input_message([&] { cnc::sim::load_machine(machine + "x", {}); }),
                         "--machine " + machine + "x: no such machine file"));
}

TEST(ScenarioMachine, TheScenarioNamesAMachineFileAndItsOwnKeysWin) {
    write_file("machine.toml", kMachine);
    const std::string scenario = write_file(
        "s.toml", "[scenario]\njob = \"square.nc\"\nmachine = \"machine.toml\"\n[machine.y]\nmicrosteps = 8\n");
    const cnc::sim::Scenario s = cnc::sim::load_scenario(scenario, {});
    EXPECT_DOUBLE_EQ(s.machine.x.steps_per_mm(), 80.0);
    EXPECT_DOUBLE_EQ(s.machine.y.steps_per_mm(), 40.0);
    const cnc::sim::Scenario own = cnc::sim::load_scenario(scenario, {"machine.x.microsteps=4"});
    EXPECT_DOUBLE_EQ(own.machine.x.steps_per_mm(), 20.0);  // 200 x 4 / 40 mm
}

TEST(ScenarioMachine, AJobOrAMachineFileWhereAScenarioBelongsSaysWhatToDo) {
    const std::string job = write_file("badge.nc", "; a badge\nG1 X10 F600\n");
    const std::string err = bad_input_message([&] { cnc::sim::load_scenario(job, {}); });
    EXPECT_TRUE(contains(err, job + ": is a job file, not a scenario (TOML): `cncsim run " + job + "`")) << err;
    const std::string machine = write_file("m.toml", kMachine);
    EXPECT_TRUE(contains(bad_input_message([&] { cnc::sim::load_scenario(machine, {}); }),
                         "a machine file, not a scenario; run a job on it with `cncsim run JOB.nc --machine"));
}

TEST(Keys, APrefixChoosesTheKeysThatStartWithIt) {
    const std::vector<cnc::sim::KeyDoc> all = cnc::sim::scenario_keys();
    const std::vector<cnc::sim::KeyDoc> x = cnc::sim::keys_with_prefix(all, "machine.x");
    ASSERT_FALSE(x.empty());
    for (const auto& d : x) EXPECT_EQ(d.key.rfind("machine.x.", 0), 0U) << d.key;
    EXPECT_TRUE(std::any_of(x.begin(), x.end(), [](const auto& d) { return d.key == "machine.x.microsteps"; }));
    const std::string err = bad_input_message([&] { cnc::sim::keys_with_prefix(all, "machin.x"); });
    EXPECT_TRUE(contains(err, "keys machin.x: no key starts with 'machin.x' (the tables: scenario, machine,")) << err;
}

TEST(Keys, WrapKeepsLinesWithinTheWidth) {
    EXPECT_EQ(cnc::sim::wrap_text("aa bb cc", 5, "# "), "# aa\n# bb\n# cc\n");
    EXPECT_EQ(cnc::sim::wrap_text("aa bb cc", 8, "# "), "# aa bb\n# cc\n");
    EXPECT_EQ(cnc::sim::wrap_text("a longword b", 4, ""), "a\nlongword\nb\n");  // a longer word alone
    const std::string text = cnc::sim::keys_text(cnc::sim::scenario_keys(), 60);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        EXPECT_TRUE(line.size() <= 60 || line.find(' ', line.find_first_not_of(' ')) == std::string::npos) << line;
    }
}

TEST(Init, TheFilesHoldEveryKeyWithItsMeaning) {
    const std::vector<cnc::sim::KeyDoc> keys = cnc::sim::scenario_keys();
    const std::vector<cnc::sim::StarterFile> files = cnc::sim::starter_files(keys);
    ASSERT_EQ(files.size(), 3U);
    EXPECT_EQ(files[0].name, "scenario.toml");
    EXPECT_EQ(files[1].name, "machine.toml");
    EXPECT_EQ(files[2].name, "job.nc");
    for (const auto& f : {files[0], files[1]}) {
        EXPECT_NO_THROW((void)toml::parse(f.text)) << f.name;
    }
    for (const cnc::sim::KeyDoc& d : keys) {
        if (d.type == cnc::sim::kArrayOfTables) continue;  // its tables' keys are checked
        const std::string& text = cnc::sim::is_machine_key(d.key) ? files[1].text : files[0].text;
        const std::string table = d.key.substr(0, d.key.rfind('.'));
        const std::string name = d.key.substr(table.size() + 1);
        // An array of tables ("events[]") is an example, its header commented out as its keys.
        const bool array = table.size() > 2 && table.compare(table.size() - 2, 2, "[]") == 0;
        const std::size_t at =
            text.find(array ? "# [[" + table.substr(0, table.size() - 2) + "]]\n" : "\n[" + table + "]\n");
        ASSERT_NE(at, std::string::npos) << d.key;
        const std::string section = text.substr(at, text.find("\n[", at + 1) - at);
        EXPECT_TRUE(contains(section, "\n" + name + " = ") ||
                    contains(section, "\n# " + name + " = " + d.default_text + "\n"))
            << d.key;
    }
    // The machine file sets nothing: the default machine.
    const toml::table machine = toml::parse(files[1].text);
    std::function<void(const toml::table&)> no_values = [&](const toml::table& t) {
        for (const auto& [k, n] : t) {
            ASSERT_TRUE(n.is_table()) << k.str();
            no_values(*n.as_table());
        }
    };
    no_values(machine);
}
