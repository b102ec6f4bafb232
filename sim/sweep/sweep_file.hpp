// A sweep file (docs/sweeps.md): the scenario or job every point runs, the architectures, the keys to vary and how
// (a list of values, a range with a step, a log range; as a full grid or zipped), the random seeds and the metrics
// to collect. Read and checked here without running anything: every message names the file, the line and the key.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cnc::sim {

// One value of a swept key: as `--set key=VALUE` gives it to the run (TOML), and as tables and plots show it.
struct SweepValue {
    std::string toml;
    std::string shown;
    bool numeric = false;
    double number = 0.0;  // when numeric
};

struct SweepAxis {
    std::string key;  // a scenario key (cncsim keys)
    int line = 0;
    std::vector<SweepValue> values;
};

// A `--set key=value` the sweep file gives every point (of the file, or of one study).
struct SweepSet {
    std::string assignment;
    std::string key;
    int line = 0;
};

// One study: its axes as a grid (every combination) or zipped (the i-th values together).
struct SweepStudy {
    std::string name;
    int line = 0;
    bool zip = false;
    std::vector<SweepSet> sets;
    std::vector<SweepAxis> axes;
};

// A metric: a JSON pointer into a point's report; "/{arch}/..." reads the architecture's own section, as
// compare's rows of the architecture section do.
struct SweepMetric {
    std::string pointer;
    int line = 0;
};

// A condition a search asks of a point's report: its metric at most `max` and at least `min` (those given).
struct SweepCondition {
    SweepMetric metric;
    std::optional<double> max;
    std::optional<double> min;
};

// [search]: the largest value of `key` in [from, to] for which every condition holds, per architecture, by bisection
// until the value that holds and the one that fails are at most `tolerance` apart; the values tried are from + k x
// tolerance, and `to`. The conditions are taken to hold at `from` (not run) and to fail above the answer once they
// fail. Its points form the file's one study, named "search": `key` and each key of `with` (set to the same value)
// zipped, the values added as the search tries them.
struct SweepSearch {
    int line = 0;
    double from = 0.0;
    double to = 0.0;
    double tolerance = 0.0;
    std::vector<SweepCondition> holds;
};

struct SweepSpec {
    std::string file;     // the sweep file as given
    std::string input;    // the scenario or job every point runs, resolved against the sweep file's folder
    bool job = false;     // `job` rather than `scenario`
    std::string machine;  // with a job: its machine file (resolved), or empty for the default machine
    int input_line = 0;
    std::vector<std::string> architectures;  // empty: the scenario's own
    int architectures_line = 0;
    std::vector<std::int64_t> seeds;  // scenario.seed of each point; empty: the scenario's own
    int seeds_line = 0;
    std::vector<SweepSet> sets;
    std::vector<SweepMetric> metrics;
    int metrics_line = 0;
    std::vector<SweepStudy> studies;
    std::optional<SweepSearch> search;

    // "FILE:LINE: what" for messages.
    [[nodiscard]] std::string where(int line, const std::string& what) const;
};

// Reads and checks the file's own structure: BadInput naming FILE:LINE and the key for an unknown key, a value of
// the wrong type, an empty value list, a range with step 0 or that never reaches its end, a log range through 0, a
// zip of lists of different lengths. Whether the scenario takes each key and value is checked by loading each
// point's scenario (sweep_check.hpp).
SweepSpec read_sweep_file(const std::string& path);

// The values of a range: from, from + step, ... up to `to` (within a billionth of the step); of a log range,
// `count` values from `from` to `to` in equal ratios. Each rounded to 12 significant digits, so that 0.1 x 3 is
// 0.3 and 250 x 2^(3/3) is 2000. Throws std::invalid_argument saying what is wrong.
std::vector<double> linear_range(double from, double to, double step);
std::vector<double> log_range(double from, double to, std::int64_t count);

// How a number is shown and set: the shortest text that reads back as it ("250", "0.3", "1e-05").
std::string number_text(double v);

}  // namespace cnc::sim
