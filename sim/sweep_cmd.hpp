// `cncsim sweep SWEEP.toml --out DIR [--jobs N]` (docs/sweeps.md): the sweep file read and every point checked, the
// points not done yet run as `cncsim run` children, then results.csv, results.json, summary.md and the plots.
#pragma once
#include <cstddef>
#include <string>

namespace cnc::sim {

// jobs 0: as many as the machine has cores. Returns the exit code: 0 every point ok, 1 some point failed (the
// results list it), 2 bad input, 130 interrupted (run the same command again to resume).
int cmd_sweep(const std::string& file, const std::string& out_dir, std::size_t jobs);

}  // namespace cnc::sim
