// What `cncsim analyze --commanded REPORT.json` needs from a run to split pulse runs where the command changed,
// as the run did: the commanded rate segments of a controller that changes rates on its own schedule (seed 004's
// FPGA: one per applied rate word, RunInput::rate_segments), written into the `--detail` report; or, for a controller
// that runs one rate per move (the seed 000 FPGA, the seed 003 timers), the moves' first STEP edges, which every
// report has.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "metrics/run_input.hpp"

namespace cnc::metrics {

// The report's "commanded_rates": per axis (in RunInput::axes order) its label, segment start times in ps and
// commanded rates in steps/s (exact doubles: analyze recomputes the run's rate errors from them).
[[nodiscard]] nlohmann::json commanded_rates_json(const RunInput& in);

// The rate segments of the run whose report is `report` (read from `filename`), for `axes` axes given in the run's
// axis order: its "commanded_rates", or one segment per move from the move's first STEP edge (rate unknown: no rate
// error). Throws BadInput naming the file when the report is not a cncsim run report, holds another number of
// axes, or had rate segments but was written without --detail ("commanded_rates": null).
[[nodiscard]] std::vector<std::vector<RateSegment>> commanded_rates_from_report(const nlohmann::json& report,
                                                                                const std::string& filename,
                                                                                std::size_t axes);

}  // namespace cnc::metrics
