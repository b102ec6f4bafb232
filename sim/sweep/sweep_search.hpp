// [search] (sweep_file.hpp): the bisection of one architecture, and the search of every architecture at once, each
// value tried a point of the sweep's one study (its report and record under points/ as any point's: a rerun reuses
// them, since the same outcomes ask for the same values again).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_file.hpp"
#include "sweep/sweep_run.hpp"

namespace cnc::sim {

class Bisection {
public:
    Bisection(double from, double to, double tolerance);
    // The value to try next; none when the search is over.
    [[nodiscard]] std::optional<double> next() const;
    // Whether the conditions held at next().
    void record(bool holds);
    // The largest value tried that held (from, not tried, when none did), and the smallest that failed.
    [[nodiscard]] double good() const { return m_good; }
    [[nodiscard]] std::optional<double> bad() const { return m_bad; }
    [[nodiscard]] bool any_held() const { return m_any_held; }
    [[nodiscard]] const std::vector<std::pair<double, bool>>& tried() const { return m_tried; }

private:
    double m_from, m_to, m_tolerance;
    double m_good;
    std::optional<double> m_bad;
    bool m_any_held = false;
    std::vector<std::pair<double, bool>> m_tried;
};

// Whether a point's report meets every condition (a failed run meets none).
[[nodiscard]] bool conditions_hold(const SweepSpec& spec, const nlohmann::json& report,
                                   const std::string& architecture);

struct SearchResult {
    std::string architecture;
    Bisection bisection;
};

// The first point of each architecture's search (at `to`), as run_search makes it: what is checked before it runs.
std::vector<SweepPoint> first_search_points(SweepSpec& spec, const std::vector<std::string>& architectures);

// Runs the search on every architecture, the next value of each at once (up to options.jobs). Points are added to
// spec.studies[0] and `points` as they are tried. Empty when interrupted (run_points' outcome in `outcome`).
std::vector<SearchResult> run_search(SweepSpec& spec, const std::vector<std::string>& architectures,
                                     const SweepRunOptions& options, std::vector<SweepPoint>& points,
                                     SweepRunOutcome& outcome,
                                     const std::function<void(const SweepPoint&)>& after_point);

// search.md: per architecture the answer and the values tried; search.json the same.
std::string search_md(const SweepSpec& spec, const std::vector<SearchResult>& results);
nlohmann::json search_json(const SweepSpec& spec, const std::vector<SearchResult>& results);

}  // namespace cnc::sim
