// `cncsim sweep`: every point not done yet as its own `cncsim run` child, up to `jobs` at once, with a progress line
// on stderr. Each child writes its report to OUT/points/ID.json (the run writes it as .partial and renames it when
// complete) and its stderr to OUT/points/ID.log; when it ends by itself its record OUT/points/ID.done.json follows
// (written the same way), which a rerun reads to skip the point. SIGINT or SIGTERM stops the sweep: no new child
// starts, the running ones get SIGINT and leave no record, and the next run of the same command resumes.
#pragma once
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/sweep_points.hpp"

namespace cnc::sim {

struct SweepRunOptions {
    std::string self_exe;            // cncsim itself
    std::vector<std::string> input;  // the run's input: the scenario, or the job and --machine M
    std::filesystem::path out_dir;
    std::size_t jobs = 1;
};

struct SweepRunOutcome {
    std::size_t already_done = 0;  // by an earlier run
    std::size_t ran = 0;           // children that ended by themselves in this run
    std::size_t failed = 0;        // of all points done, those whose child did not exit 0
    bool interrupted = false;
};

// A file's whole text (empty when it cannot be read): a point's log and record, a submission's files.
std::string read_text(const std::filesystem::path& path);

std::filesystem::path point_report(const std::filesystem::path& out_dir, const SweepPoint& p);
std::filesystem::path point_record(const std::filesystem::path& out_dir, const SweepPoint& p);
// The point's record, when it has one that reads (a rerun's and the results' view of it).
std::optional<PointRecord> read_point_record(const std::filesystem::path& out_dir, const SweepPoint& p);

// `after_point` is called on each point whose child exited 0, in the order they end; an exception from it (a
// metric the report lacks) stops the sweep as an interruption does, then leaves run_points.
SweepRunOutcome run_points(const std::vector<SweepPoint>& points, const SweepRunOptions& options,
                           const std::function<void(const SweepPoint&)>& after_point);

}  // namespace cnc::sim
