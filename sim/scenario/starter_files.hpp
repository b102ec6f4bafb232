// `cncsim init`: a scenario, its machine file and a small job to start from. The keys and their comments come
// from the key registry (scenario_keys), so the files say what the loader reads.
#pragma once
#include <string>
#include <vector>

#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct StarterFile {
    std::string name;  // in the folder init writes to
    std::string text;
};

// scenario.toml (every key but the machine's, the job, architecture and machine file set, the rest commented out
// at its default), machine.toml (the machine's keys, commented out: the default machine) and job.nc (a 10 mm
// square). The scenario runs as written.
std::vector<StarterFile> starter_files(const std::vector<KeyDoc>& docs);

}  // namespace cnc::sim
