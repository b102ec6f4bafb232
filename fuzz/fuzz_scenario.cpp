// libFuzzer harness: the scenario loader (scenario/scenario.hpp), TOML and --set overrides. The input is the
// scenario file up to its first NUL byte; each line after it is one --set override. The job file is only named
// by a scenario, not read, so none needs to exist. Only cnc::BadInput may leave the loader.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"

namespace {

// load_scenario reads a file: one per fuzzing process, removed at exit. In memory (/dev/shm) where there is one:
// rewriting a file on ext4 flushes it to disk at every close, which made that most of an execution's time.
struct ScratchFile {
    std::string path = (dir() / ("cncsim_fuzz_scenario_" + std::to_string(getpid()) + ".toml")).string();
    ~ScratchFile() { std::filesystem::remove(path); }

    static std::filesystem::path dir() {
        std::error_code ec;
        return std::filesystem::is_directory("/dev/shm", ec) ? "/dev/shm" : std::filesystem::temp_directory_path();
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const ScratchFile scratch;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    {
        std::ofstream out(scratch.path, std::ios::binary | std::ios::trunc);
        out << input.substr(0, nul);
    }
    std::vector<std::string> overrides;
    if (nul != std::string::npos) {
        std::istringstream sets(input.substr(nul + 1));
        for (std::string line; std::getline(sets, line);) overrides.push_back(line);
    }
    try {
        (void)cnc::sim::load_scenario(scratch.path, overrides);
    } catch (const cnc::BadInput&) {
    }
    return 0;
}
