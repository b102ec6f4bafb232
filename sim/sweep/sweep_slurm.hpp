// A sweep on a Slurm cluster (docs/sweeps.md, "On a Slurm cluster"): the points cut into job-array tasks of
// `per_task` points each (task K runs points K x per_task ..), what the submission leaves in OUT/slurm/ (the point
// list, which `cncsim sweep collect` reads back, and the job-array script), and the `--array` list of the tasks that
// still have points to run.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace cnc::sim {

// Slurm's default MaxArraySize is 1001: task numbers up to 1000.
constexpr std::size_t kSlurmMaxTasks = 1000;

// How many tasks `points` points make at `per_task` a task.
[[nodiscard]] std::size_t task_count(std::size_t points, std::size_t per_task);
// The points per task when --points-per-task is not given: 1, or as many as keep the tasks within kSlurmMaxTasks.
[[nodiscard]] std::size_t default_points_per_task(std::size_t points);
// The first point of task `task` and one past its last.
[[nodiscard]] std::pair<std::size_t, std::size_t> task_points(std::size_t task, std::size_t points,
                                                              std::size_t per_task);
// `sbatch --array`'s list of the tasks (ascending): runs as ranges, "0-3,5,7-8".
[[nodiscard]] std::string array_list(const std::vector<std::size_t>& tasks);

// What `--slurm` submitted: how to run a task again, and each point's --set list (which collect checks the sweep
// file still gives).
struct SlurmSubmission {
    std::string sweep_file;  // as given on the command line, relative to `cwd`
    std::string out_dir;     // as given, relative to `cwd`
    std::string cwd;         // where the command ran: every task runs there
    std::string self_exe;    // cncsim, which the nodes must have at the same path
    std::size_t per_task = 1;
    std::string partition;  // empty: the cluster's default
    std::string time;       // empty: the partition's default
    std::vector<std::vector<std::string>> point_sets;
};
nlohmann::json submission_json(const SlurmSubmission& s);
// Empty when the text is not a submission (another program's file, one cut short).
std::optional<SlurmSubmission> parse_submission(const std::string& text);

// The job-array script: each task runs `cncsim sweep SWEEP --out DIR --point $SLURM_ARRAY_TASK_ID
// --points-per-task K` in `cwd`, its output in `log_pattern` (an absolute path with Slurm's %A and %a).
[[nodiscard]] std::string job_script(const SlurmSubmission& s, const std::string& log_pattern);

// A word for sh: in single quotes unless it is plain.
[[nodiscard]] std::string shell_word(const std::string& word);

}  // namespace cnc::sim
