// What a command printed on stdout, for the tests that run the cncsim executable; a nonzero exit fails the test.
#pragma once
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace cnc::test {

inline std::string command_output(const std::string& cmd) {
    FILE* pipe = popen(cmd.c_str(), "r");
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
    EXPECT_EQ(pclose(pipe), 0) << cmd;
    return text;
}

}  // namespace cnc::test
