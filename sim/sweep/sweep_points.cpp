#include "sweep/sweep_points.hpp"

#include <sstream>

#include <fmt/format.h>

namespace cnc::sim {

namespace {

// The value combinations of a study: every one of the grid (the last axis fastest), or the zipped i-th values.
std::vector<std::vector<std::size_t>> combinations(const SweepStudy& study) {
    std::vector<std::vector<std::size_t>> out;
    if (study.zip && !study.axes.empty()) {
        for (std::size_t i = 0; i < study.axes.front().values.size(); ++i) out.emplace_back(study.axes.size(), i);
        return out;
    }
    std::vector<std::size_t> at(study.axes.size(), 0);
    while (true) {
        out.push_back(at);
        std::size_t k = at.size();
        while (k > 0 && ++at[k - 1] == study.axes[k - 1].values.size()) at[--k] = 0;
        if (k == 0) return out;
    }
}

}  // namespace

std::string SweepPoint::id() const {
    return fmt::format(FMT_STRING("{:05d}"), index);
}

SweepPoint make_point(const SweepSpec& spec, std::size_t index, std::size_t study_index,
                      const std::string& architecture, const std::vector<std::size_t>& value_index,
                      std::optional<std::int64_t> seed) {
    const SweepStudy& study = spec.studies[study_index];
    SweepPoint p{index, study_index, architecture, value_index, seed, {"scenario.architecture=" + architecture}};
    for (const SweepSet& s : spec.sets) p.sets.push_back(s.assignment);
    for (const SweepSet& s : study.sets) p.sets.push_back(s.assignment);
    for (std::size_t a = 0; a < value_index.size(); ++a)
        p.sets.push_back(study.axes[a].key + "=" + study.axes[a].values[value_index[a]].toml);
    if (seed) p.sets.push_back("scenario.seed=" + std::to_string(*seed));
    return p;
}

std::vector<std::string> point_architectures(const SweepSpec& spec, const std::string& default_architecture) {
    return spec.architectures.empty() ? std::vector<std::string>{default_architecture} : spec.architectures;
}

std::vector<SweepPoint> expand_points(const SweepSpec& spec, const std::string& default_architecture) {
    const std::vector<std::optional<std::int64_t>> seeds = [&] {
        std::vector<std::optional<std::int64_t>> s(spec.seeds.begin(), spec.seeds.end());
        if (s.empty()) s.emplace_back();
        return s;
    }();
    std::vector<SweepPoint> points;
    for (std::size_t st = 0; st < spec.studies.size(); ++st) {
        const std::vector<std::vector<std::size_t>> combos = combinations(spec.studies[st]);
        for (const std::string& arch : point_architectures(spec, default_architecture)) {
            for (const std::vector<std::size_t>& combo : combos) {
                for (const std::optional<std::int64_t>& seed : seeds)
                    points.push_back(make_point(spec, points.size(), st, arch, combo, seed));
            }
        }
    }
    return points;
}

nlohmann::json record_json(const PointRecord& r) {
    return {{"sets", r.sets}, {"exit_code", r.exit_code}, {"message", r.message}};
}

std::optional<PointRecord> parse_record(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return std::nullopt;
    const auto sets = j.find("sets");
    const auto code = j.find("exit_code");
    const auto message = j.find("message");
    if (sets == j.end() || !sets->is_array() || code == j.end() || !code->is_number_integer() || message == j.end() ||
        !message->is_string())
        return std::nullopt;
    PointRecord r;
    for (const nlohmann::json& s : *sets) {
        if (!s.is_string()) return std::nullopt;
        r.sets.push_back(s.get<std::string>());
    }
    r.exit_code = code->get<int>();
    r.message = message->get<std::string>();
    return r;
}

bool point_done(const SweepPoint& point, const std::optional<PointRecord>& record) {
    return record && record->sets == point.sets;
}

std::string failure_message(const std::string& stderr_text, int exit_code) {
    std::istringstream in(stderr_text);
    std::string last;
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    }
    if (!last.empty()) return last;
    return exit_code == 0 ? "" : fmt::format(FMT_STRING("exit code {}, nothing on stderr"), exit_code);
}

}  // namespace cnc::sim
