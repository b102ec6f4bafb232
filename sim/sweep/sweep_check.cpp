#include "sweep/sweep_check.hpp"

#include <algorithm>
#include <set>

#include "architectures/catalog.hpp"
#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

namespace {

// A set key or a swept one, with where the sweep file gives it.
struct Given {
    std::string key;
    std::string value;
    int line;
};

std::vector<Given> given_keys(const SweepSpec& spec, const SweepStudy& study) {
    std::vector<Given> out;
    for (const std::vector<SweepSet>* list : {&spec.sets, &study.sets}) {
        for (const SweepSet& s : *list) out.push_back({s.key, s.assignment.substr(s.assignment.find('=') + 1), s.line});
    }
    for (const SweepAxis& a : study.axes) out.push_back({a.key, "", a.line});
    return out;
}

void check_known(const std::vector<Given>& given, const SweepSpec& spec) {
    std::set<std::string> known;
    for (const KeyDoc& d : scenario_keys()) known.insert(d.key);
    for (const Given& g : given) {
        if (known.count(g.key) == 0)
            throw BadInput(spec.where(g.line, g.key), "not a scenario key (cncsim keys lists them)");
        if (g.key == "scenario.architecture")
            throw BadInput(spec.where(g.line, g.key), "the sweep's architectures = [...] say which run");
    }
}

}  // namespace

void check_sweep(const SweepSpec& spec, const std::vector<SweepPoint>& points, const CompareInput& input) {
    for (const std::string& a : spec.architectures)
        (void)find_architecture(a, spec.where(spec.architectures_line, "architectures"));
    for (const SweepStudy& study : spec.studies) check_known(given_keys(spec, study), spec);
    for (const SweepPoint& p : points) {
        if (p.seed && !spec.seeds.empty() && *p.seed != spec.seeds.front()) continue;
        const std::vector<std::string> sets(p.sets.begin() + 1, p.sets.end());  // the architecture is its own
        const std::optional<std::string> why = why_not_runnable(input, p.architecture, sets);
        if (!why) continue;
        // The value the message names by its --set key: the last given (a swept value after the sets).
        const SweepStudy& study = spec.studies[p.study];
        std::vector<Given> given = given_keys(spec, study);
        for (std::size_t a = 0; a < study.axes.size(); ++a)
            given[given.size() - study.axes.size() + a].value = study.axes[a].values[p.value_index[a]].toml;
        const auto named = std::find_if(given.rbegin(), given.rend(), [&](const Given& g) {
            return why->find("--set " + g.key) != std::string::npos;
        });
        if (named == given.rend())
            throw BadInput(spec.where(spec.input_line, spec.job ? "job" : "scenario"), p.architecture + ": " + *why);
        throw BadInput(spec.where(named->line, named->key + " = " + named->value), p.architecture + ": " + *why);
    }
}

}  // namespace cnc::sim
