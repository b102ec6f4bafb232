// libFuzzer harness: the seed 000 steps file reader (host/core/steps_file.hpp). What it accepts must survive a
// write and a second read unchanged. Only cnc::BadInput may leave the reader.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "host/core/steps_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using cnc::host::MotionSegment;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::vector<MotionSegment> rows;
    try {
        rows = cnc::host::read_steps_file(in, "fuzz.steps");
    } catch (const cnc::BadInput&) {
        return 0;
    }
    std::stringstream file;
    cnc::host::write_steps_file(file, rows);
    const std::vector<MotionSegment> back = cnc::host::read_steps_file(file, "fuzz.steps");
    bool same = back.size() == rows.size();
    for (std::size_t i = 0; same && i < rows.size(); ++i) {
        same = back[i].index == rows[i].index && back[i].line == rows[i].line && back[i].motion == rows[i].motion &&
               back[i].steps_x == rows[i].steps_x && back[i].steps_y == rows[i].steps_y && back[i].feed == rows[i].feed;
    }
    if (!same) {
        std::fprintf(stderr, "invariant broken: a steps file read, written and read again changed\n");
        std::abort();
    }
    return 0;
}
