// Child processes of cncsim: `compare` runs one `cncsim run` per architecture, `sweep` one per point, the plots run
// gnuplot.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace cnc::sim {

// Starts argv[0] (searched on PATH) in `cwd` (empty: ours) with stdout to /dev/null, or to the file `stdout_path`
// (what sbatch answers); stderr stays the user's, or goes to the file `stderr_path` (a sweep's point log). Throws
// std::runtime_error naming the program when it cannot start.
pid_t spawn_child(const std::vector<std::string>& args, const std::string& cwd = "",
                  const std::string& stderr_path = "", const std::string& stdout_path = "");
// Waits for any child started by spawn_child; returns its pid and sets its exit code (1 if it died by a signal).
pid_t wait_any_child(int& exit_code);
// Both: runs argv and returns its exit code.
int run_child(const std::vector<std::string>& args, const std::string& cwd = "", const std::string& stdout_path = "");

}  // namespace cnc::sim
