// `cncsim sweep SWEEP.toml --out DIR [--jobs N]` (docs/sweeps.md): the sweep file read and every point checked, the
// points not done yet run as `cncsim run` children, then results.csv, results.json, summary.md and the plots. With
// --slurm the points go to a Slurm job array instead, each task a `--point K` run of the same command, and `cncsim
// sweep collect DIR` makes the same results from what the tasks have finished.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

namespace cnc::sim {

struct SweepCommand {
    std::string file;
    std::string out_dir;
    std::size_t jobs = 0;  // 0: as many as the machine has cores (one with --point)
    bool slurm = false;
    std::string partition;
    std::string time;
    std::size_t per_task = 0;  // --points-per-task; 0: not given
    std::optional<std::size_t> point;
    std::string collect_dir;  // `cncsim sweep collect DIR`
};

// Returns the exit code: 0 every point ok, 1 some point failed (the results list it) or, for collect, has not run
// yet, 2 bad input, 130 interrupted (run the same command again to resume).
int cmd_sweep(const SweepCommand& c);

}  // namespace cnc::sim
