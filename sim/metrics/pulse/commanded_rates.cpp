#include "metrics/pulse/commanded_rates.hpp"

#include <nlohmann/json.hpp>

#include "common/bad_input.hpp"
#include "metrics/pulse/edge_index.hpp"

namespace cnc::metrics {

namespace {

using nlohmann::json;

std::vector<std::vector<RateSegment>> from_segments(const json& rates, const std::string& filename, std::size_t axes) {
    if (rates.size() != axes) {
        throw BadInput(filename, "the run's report has " + std::to_string(rates.size()) + " axes, --step gives " +
                                     std::to_string(axes) + " (give them in the run's axis order)");
    }
    std::vector<std::vector<RateSegment>> out(axes);
    for (std::size_t a = 0; a < axes; ++a) {
        const json& t = rates.at(a).at("t_ps");
        const json& rate = rates.at(a).at("steps_per_s");
        for (std::size_t k = 0; k < t.size(); ++k) out[a].push_back({t.at(k).get<TimePs>(), rate.at(k).get<double>()});
    }
    return out;
}

// One segment per move with edges, from its first edge: a move's edges are the ones before the next move's first.
std::vector<std::vector<RateSegment>> from_moves(const json& first_edges, std::size_t axes) {
    std::vector<RateSegment> segments;
    for (const json& t : first_edges) {
        if (!t.is_null()) segments.push_back({t.get<TimePs>(), 0.0});
    }
    return std::vector<std::vector<RateSegment>>(axes, segments);
}

}  // namespace

json commanded_rates_json(const RunInput& in) {
    json out = json::array();
    for (std::size_t a = 0; a < in.rate_segments.size() && a < in.axes.size(); ++a) {
        json t = json::array();
        json rate = json::array();
        for (const RateSegment& s : in.rate_segments[a]) {
            t.push_back(s.t_ps);
            rate.push_back(s.steps_per_s);
        }
        out.push_back({{"axis", axis_label(in, a)}, {"t_ps", std::move(t)}, {"steps_per_s", std::move(rate)}});
    }
    return out;
}

std::vector<std::vector<RateSegment>> commanded_rates_from_report(const json& report, const std::string& filename,
                                                                  std::size_t axes) {
    try {
        if (report.contains("commanded_rates")) {
            const json& rates = report.at("commanded_rates");
            if (rates.is_null()) {
                throw BadInput(filename,
                               "the run changed its commanded rates on its own schedule and this report "
                               "does not hold them: write it with `cncsim run --detail`");
            }
            return from_segments(rates, filename, axes);
        }
        // Pulse runs are split per executed piece (chord, command); a report without --detail holds only the
        // programmed moves, which is the same for a job of straight lines.
        const json& metrics = report.at("metrics");
        const json& pieces = metrics.contains("pieces") ? metrics.at("pieces") : metrics.at("moves");
        return from_moves(pieces.at("t_first_edge_ps"), axes);
    } catch (const json::exception& e) {
        throw BadInput(filename, std::string("not a cncsim run report (") + e.what() + ")");
    }
}

}  // namespace cnc::metrics
