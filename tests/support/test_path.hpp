// A file path of the running test's own, in this build tree: <build>/test_out/<suite>.<test>/<name>. ctest runs
// every TEST as its own process, many at once (-j8) but never one test twice at once, so no two running tests share
// a path; and the folder is not /tmp, which the test runs of other checkouts on the machine share.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace cnc::test {

inline std::string test_path(const std::string& name) {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string folder = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(folder.begin(), folder.end(), '/', '_');  // parameterised tests: Suite/Name/0
    const std::filesystem::path dir = std::filesystem::path(CNC_TEST_OUT_DIR) / folder;
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

}  // namespace cnc::test
