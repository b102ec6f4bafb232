// The run's report: the metrics as JSON (to_json) and as the summary the CLI prints (summary_table), and the JSON
// report's file text, with a long job's per-move columns written straight from the records.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "metrics/metrics.hpp"

namespace cnc::metrics {

// Where the JSON report's per-move columns of the programmed moves go: into the json, or left null there for
// write_move_columns() to write from RunMetrics::moves straight to the file (a long job's largest part of the
// report: as json values it would hold the records a second time).
enum class MoveColumns { InJson, Streamed };
// `detail` false: without the pulse runs and the dead-time gaps (cncsim run without --detail); analyze writes all.
[[nodiscard]] nlohmann::json to_json(const RunMetrics& m, bool detail = true,
                                     MoveColumns columns = MoveColumns::InJson);
// The programmed moves' columns as report_text() writes to_json()'s "moves" at `depth`: one pass over the
// records per column.
void write_move_columns(std::ostream& out, const RunMetrics& m, bool detail, int depth);
[[nodiscard]] std::string summary_table(const RunMetrics& m);

// A member of the report written from elsewhere: at `path` (object keys from the top) the json holds a
// placeholder, and `write(out, depth)` writes the value instead.
struct StreamedMember {
    std::vector<std::string> path;
    std::function<void(std::ostream& out, int depth)> write;
};
// The JSON report as the file holds it: indented by kReportIndent per level, with each array of plain values on one
// line.
inline constexpr int kReportIndent = 2;
void write_report_text(std::ostream& out, const nlohmann::json& report, const StreamedMember* member = nullptr);
[[nodiscard]] std::string report_text(const nlohmann::json& report);

}  // namespace cnc::metrics
