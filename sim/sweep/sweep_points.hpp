// A sweep's points: every study's combinations of values, on every architecture, with every seed; each point the
// `--set` list its `cncsim run` child gets. And what a finished point leaves in the output folder, which a rerun
// reads to skip it (docs/sweeps.md, "Resume").
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_file.hpp"

namespace cnc::sim {

struct SweepPoint {
    std::size_t index = 0;  // in expansion order: study, architecture, values (the first axis slowest), seed
    std::size_t study = 0;  // into SweepSpec::studies
    std::string architecture;
    std::vector<std::size_t> value_index;  // per axis of the study: which of its values
    std::optional<std::int64_t> seed;
    // The child's --set list, in the order it applies them: the architecture, the file's sets, the study's, the
    // swept values, the seed.
    std::vector<std::string> sets;

    // Its files' stem under the output folder's points/: "00042".
    [[nodiscard]] std::string id() const;
};

// The file's architectures, or `default_architecture` (the scenario's own) when it names none.
std::vector<std::string> point_architectures(const SweepSpec& spec, const std::string& default_architecture);
std::vector<SweepPoint> expand_points(const SweepSpec& spec, const std::string& default_architecture);
// One point: the study's values value_index (one per axis) on `architecture`, with its --set list.
SweepPoint make_point(const SweepSpec& spec, std::size_t index, std::size_t study, const std::string& architecture,
                      const std::vector<std::size_t>& value_index, std::optional<std::int64_t> seed);

// A point's record (points/ID.done.json), written when its child ended by itself: the sets it ran with, the
// child's exit code and, when it failed, its message (its last line on stderr).
struct PointRecord {
    std::vector<std::string> sets;
    int exit_code = 0;
    std::string message;
};
nlohmann::json record_json(const PointRecord& r);
// Empty when the text is no record (a file cut short, another program's).
std::optional<PointRecord> parse_record(const std::string& text);

// Whether a rerun skips the point: its record is there, and was written for the same sets (a sweep file changed
// since gives the point's index other sets: it runs again).
[[nodiscard]] bool point_done(const SweepPoint& point, const std::optional<PointRecord>& record);

// The message of a failed child: the last non-empty line of its stderr, or its exit code when it printed nothing.
std::string failure_message(const std::string& stderr_text, int exit_code);

}  // namespace cnc::sim
