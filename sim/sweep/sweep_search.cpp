#include "sweep/sweep_search.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "compare/compare.hpp"
#include "sweep/sweep_points.hpp"
#include "sweep/sweep_results.hpp"

namespace cnc::sim {

namespace {

// A search's points: architecture k's i-th value is point k x kProbesPerArchitecture + i.
constexpr std::size_t kProbesPerArchitecture = 1000;

std::size_t value_index(SweepStudy& study, double v) {
    std::vector<SweepValue>& values = study.axes.front().values;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i].number == v) return i;
    }
    for (SweepAxis& a : study.axes) a.values.push_back({number_text(v), number_text(v), true, v});
    return values.size() - 1;
}

std::string condition_text(const SweepCondition& c) {
    std::string out = c.metric.pointer;
    if (c.min) out = number_text(*c.min) + " <= " + out;
    if (c.max) out += " <= " + number_text(*c.max);
    return out;
}

}  // namespace

Bisection::Bisection(double from, double to, double tolerance)
    : m_from(from), m_to(to), m_tolerance(tolerance), m_good(from) {}

std::optional<double> Bisection::next() const {
    if (m_tried.empty()) return m_to;
    if (!m_bad || *m_bad - m_good <= m_tolerance) return std::nullopt;
    // The middle, on the grid from + k x tolerance so that the values tried are round and shared between
    // architectures; moved by a step when rounding lands it on an end.
    double mid = m_from + std::round(((m_good + *m_bad) / 2.0 - m_from) / m_tolerance) * m_tolerance;
    mid = std::stod(fmt::format(FMT_STRING("{:.12g}"), mid));
    if (mid <= m_good) mid += m_tolerance;
    if (mid >= *m_bad) mid -= m_tolerance;
    if (mid <= m_good || mid >= *m_bad) return std::nullopt;
    return mid;
}

void Bisection::record(bool holds) {
    const std::optional<double> v = next();
    if (!v) return;
    m_tried.emplace_back(*v, holds);
    if (holds) {
        m_good = *v;
        m_any_held = true;
    } else {
        m_bad = *v;
    }
}

bool conditions_hold(const SweepSpec& spec, const nlohmann::json& report, const std::string& architecture) {
    for (const SweepCondition& c : spec.search->holds) {
        const std::optional<double> v = report_number(report, metric_pointer(c.metric, architecture));
        if (!v || (c.max && *v > *c.max) || (c.min && *v < *c.min)) return false;
    }
    return true;
}

std::vector<SweepPoint> first_search_points(SweepSpec& spec, const std::vector<std::string>& architectures) {
    std::vector<SweepPoint> out;
    const std::size_t k = value_index(spec.studies.front(), spec.search->to);
    for (std::size_t a = 0; a < architectures.size(); ++a) {
        out.push_back(make_point(spec, a * kProbesPerArchitecture, 0, architectures[a],
                                 std::vector<std::size_t>(spec.studies.front().axes.size(), k), std::nullopt));
    }
    return out;
}

std::vector<SearchResult> run_search(SweepSpec& spec, const std::vector<std::string>& architectures,
                                     const SweepRunOptions& options, std::vector<SweepPoint>& points,
                                     SweepRunOutcome& outcome,
                                     const std::function<void(const SweepPoint&)>& after_point) {
    const SweepSearch& search = *spec.search;
    std::vector<SearchResult> results;
    for (const std::string& a : architectures)
        results.push_back({a, Bisection(search.from, search.to, search.tolerance)});
    std::vector<std::size_t> tried(architectures.size(), 0);
    while (true) {
        std::vector<SweepPoint> round;
        std::vector<std::size_t> arch_of;
        for (std::size_t a = 0; a < results.size(); ++a) {
            const std::optional<double> v = results[a].bisection.next();
            if (!v) continue;
            const std::size_t k = value_index(spec.studies.front(), *v);
            round.push_back(make_point(spec, a * kProbesPerArchitecture + tried[a]++, 0, architectures[a],
                                       std::vector<std::size_t>(spec.studies.front().axes.size(), k), std::nullopt));
            arch_of.push_back(a);
        }
        if (round.empty()) return results;
        const SweepRunOutcome o = run_points(round, options, after_point);
        outcome.already_done += o.already_done;
        outcome.ran += o.ran;
        outcome.failed += o.failed;
        if (o.interrupted) {
            outcome.interrupted = true;
            return {};
        }
        for (std::size_t i = 0; i < round.size(); ++i) {
            const std::optional<PointRecord> record = read_point_record(options.out_dir, round[i]);
            std::ifstream in(point_report(options.out_dir, round[i]));
            const nlohmann::json report = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
            const bool ok = record && record->exit_code == 0 && report.is_object();
            results[arch_of[i]].bisection.record(ok && conditions_hold(spec, report, round[i].architecture));
            points.push_back(round[i]);
        }
    }
}

nlohmann::json search_json(const SweepSpec& spec, const std::vector<SearchResult>& results) {
    nlohmann::json out = nlohmann::json::array();
    for (const SearchResult& r : results) {
        nlohmann::json tried = nlohmann::json::array();
        for (const auto& [v, holds] : r.bisection.tried()) tried.push_back({{"value", v}, {"holds", holds}});
        out.push_back({{"architecture", r.architecture},
                       {"largest", r.bisection.any_held() ? nlohmann::json(r.bisection.good()) : nlohmann::json()},
                       {"smallest_failing", r.bisection.bad() ? nlohmann::json(*r.bisection.bad()) : nlohmann::json()},
                       {"tried", tried}});
    }
    std::vector<std::string> conditions;
    for (const SweepCondition& c : spec.search->holds) conditions.push_back(condition_text(c));
    return {{"sweep", spec.file},    {"key", spec.studies.front().axes.front().key}, {"from", spec.search->from},
            {"to", spec.search->to}, {"tolerance", spec.search->tolerance},          {"holds", conditions},
            {"architectures", out}};
}

std::string search_md(const SweepSpec& spec, const std::vector<SearchResult>& results) {
    const SweepSearch& s = *spec.search;
    std::string conditions;
    for (const SweepCondition& c : s.holds) conditions += (conditions.empty() ? "" : " and ") + condition_text(c);
    std::ostringstream os;
    os << "# Search " << spec.file << "\n\n"
       << fmt::format(FMT_STRING("The largest {} in [{}, {}] at which {} (to {}; {} is taken to hold, not run)."),
                      spec.studies.front().axes.front().key, number_text(s.from), number_text(s.to), conditions,
                      number_text(s.tolerance), number_text(s.from))
       << "\n\n| architecture | largest that holds | smallest that fails | values tried (y: holds) "
          "|\n|---|---|---|---|\n";
    for (const SearchResult& r : results) {
        std::string tried;
        for (const auto& [v, holds] : r.bisection.tried())
            tried += (tried.empty() ? "" : ", ") + number_text(v) + (holds ? " y" : " n");
        os << "| " << r.architecture << " | "
           << (r.bisection.any_held() ? number_text(r.bisection.good()) : "none above " + number_text(s.from)) << " | "
           << (r.bisection.bad() ? number_text(*r.bisection.bad()) : "none up to " + number_text(s.to)) << " | "
           << tried << " |\n";
    }
    return os.str();
}

}  // namespace cnc::sim
