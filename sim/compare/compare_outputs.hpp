// `cncsim compare --out DIR`: after the runs (their reports, VCDs and plot data already in DIR), the table as
// Markdown, CSV and JSON, the plots of every architecture together, and index.html.
#pragma once
#include <string>
#include <vector>

#include "compare/compare.hpp"

namespace cnc::sim {

// scenario_label and scenario_text: the scenario file and its text, or for a job the machine file (or "the
// default machine") and its text; job_path: the job, resolved. Prints the plotting time on stderr.
void write_compare_outputs(const Comparison& comparison, const std::string& scenario_label,
                           const std::string& scenario_text, const std::vector<std::string>& sets,
                           const std::string& job_path, const std::string& out_dir);

}  // namespace cnc::sim
