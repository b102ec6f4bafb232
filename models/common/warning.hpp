// Warnings with a kind, and their grouping for the reports: a long job can raise the same warning on hundreds of
// lines, and the summary and the JSON report list each kind once, with a count and the first places.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace cnc {

struct Warning {
    std::string kind;   // one key per cause ("ocr0a_range", "period_overflow"): what the grouping goes by
    std::string where;  // "job.nc:12", "segment 17 (line 20)"; empty for a count over the whole run
    std::string text;
};

// "where: text", or the text alone.
[[nodiscard]] std::string to_string(const Warning& w);

inline constexpr std::size_t kWarningPlacesShown = 3;

struct WarningGroup {
    std::string kind;
    std::size_t count = 0;
    std::vector<std::string> first;    // the first kWarningPlacesShown places (warnings without one add none)
    std::string message;               // the first warning's text
    std::vector<std::size_t> members;  // indices of the group's warnings, in order
};

// One group per kind, in the order the kinds first appear.
[[nodiscard]] std::vector<WarningGroup> group_warnings(const std::vector<Warning>& warnings);

// The summary's line for a group, without the trailing newline: a single warning as to_string() words it; several
// as "N x kind at a, b, c, ...; first: the first one's text".
[[nodiscard]] std::string summary_line(const WarningGroup& g);

}  // namespace cnc
