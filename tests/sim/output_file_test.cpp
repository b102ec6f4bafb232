// Output files (sim/output/output_file.hpp): a file is complete under its name or not there at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/bad_input.hpp"
#include "output/output_file.hpp"

namespace fs = std::filesystem;
using cnc::sim::OutputFile;

namespace {

// A folder of the test's own (ctest runs the tests of this file in parallel processes).
fs::path test_dir() {
    const fs::path dir =
        fs::path(::testing::TempDir()) /
        ("output_file_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(OutputFile, WrittenAsPartialAndRenamedWhenComplete) {
    const fs::path dir = test_dir();
    const fs::path path = dir / "r.json";
    std::ofstream(path) << "an older report";
    OutputFile f(path.string(), "--report");
    EXPECT_FALSE(fs::exists(path));  // the older file would claim to be this run's
    f.stream() << "new";
    EXPECT_TRUE(fs::exists(dir / "r.json.partial"));
    f.close();
    EXPECT_EQ(read(path), "new");
    EXPECT_FALSE(fs::exists(dir / "r.json.partial"));
}

TEST(OutputFile, AbandonedFileLeavesNothing) {
    const fs::path dir = test_dir();
    {
        OutputFile f((dir / "t.vcd").string(), "--vcd");
        f.stream() << "half a trace";
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(OutputFile, WriteErrorOnADeviceFailsTheRun) {
    OutputFile f("/dev/full", "--report");
    f.stream() << std::string(1 << 16, 'x');
    try {
        f.close();
        ADD_FAILURE() << "no OutputError";
    } catch (const cnc::sim::OutputError& e) {
        EXPECT_STREQ(e.what(), "cannot write /dev/full (--report): No space left on device");
    }
}

TEST(OutputFile, PathsThatCannotBeWrittenAreBadInput) {
    const fs::path dir = test_dir();
    const auto message = [](const std::string& path) {
        try {
            cnc::sim::check_output_path(path, "--vcd");
        } catch (const cnc::BadInput& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message(dir.string()), "--vcd " + dir.string() + ": is a folder, not a file");
    EXPECT_EQ(message((dir / "missing" / "t.vcd").string()), "--vcd " + (dir / "missing" / "t.vcd").string() +
                                                                 ": its folder " + (dir / "missing").string() +
                                                                 " does not exist");
    EXPECT_EQ(message(""), "--vcd: the output file name is empty");
    EXPECT_EQ(message((dir / "t.vcd").string()), "");
    EXPECT_EQ(message("/dev/null"), "");
}
