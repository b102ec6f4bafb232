// `cncsim init [DIR]`: writes a scenario, its machine file and a small job to start from (scenario/starter_files)
// into DIR, which it creates if needed; a file already there stops it before anything is written.
#pragma once
#include <ostream>
#include <string>

namespace cnc::sim {

// Writes the files and says on `out` what they are and how to run them; returns the exit code.
int cmd_init(const std::string& dir, std::ostream& out);

}  // namespace cnc::sim
