#include "compare/compare_check.hpp"

#include <algorithm>

#include "architectures/catalog.hpp"
#include "common/bad_input.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

std::optional<std::string> why_not_runnable(const CompareInput& input, const std::string& architecture,
                                            const std::vector<std::string>& sets) {
    // The child's own order: the architecture first, then the user's --set.
    std::vector<std::string> overrides = {"scenario.architecture=" + architecture};
    overrides.insert(overrides.end(), sets.begin(), sets.end());
    try {
        const Scenario s = input.load(overrides);
        const Architecture& a = find_architecture(s.architecture, s.file + ": scenario.architecture");
        if (a.job_use().runs_job) (void)load_job(s, a);
    } catch (const BadInput& e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

void check_compare_columns(const CompareInput& input, const std::vector<CompareColumn>& columns,
                           const std::vector<std::string>& sets, const std::string& variants_from) {
    std::vector<std::string> architectures;
    for (const CompareColumn& c : columns) {
        if (c.variant.empty()) {
            architectures.push_back(c.architecture);
            continue;
        }
        std::vector<std::string> with_variant = sets;
        with_variant.insert(with_variant.end(), c.variant_sets.begin(), c.variant_sets.end());
        // A variant is the user's own design: the first that cannot run is named, whatever the others do.
        if (const std::optional<std::string> why = why_not_runnable(input, c.architecture, with_variant))
            throw BadInput(variants_from + " " + c.variant,
                           "compare " + input.name + ": " + c.label() + " cannot run it: " + *why);
    }
    std::string runnable;              // "a,b": for --arch
    std::string refused;               // "ARCH cannot run it: why; ..."
    std::vector<std::string> reasons;  // each different reason once
    for (const std::string& a : architectures) {
        const std::optional<std::string> why = why_not_runnable(input, a, sets);
        if (!why) {
            runnable += (runnable.empty() ? "" : ",") + a;
            continue;
        }
        refused += (refused.empty() ? "" : "; ") + a + " cannot run it: " + *why;
        if (std::find(reasons.begin(), reasons.end(), *why) == reasons.end()) reasons.push_back(*why);
    }
    if (refused.empty()) return;
    // Said as `cncsim run` says it when no column differs.
    if (runnable.empty() && reasons.size() == 1) throw BadInput("", reasons.front());
    const std::string what = "compare " + input.name + ": " + refused;
    if (runnable.empty()) throw BadInput("", what);
    // A table with a column of nothing is no comparison: the user picks the columns that can be compared.
    throw BadInput("--arch", what + "; compare those that can with --arch " + runnable);
}

bool baseline_runs(const CompareInput& input, const std::vector<CompareColumn>& columns,
                   const std::vector<std::string>& sets, std::ostream& log) {
    const Architecture* baseline = baseline_architecture();
    if (baseline == nullptr) return false;
    const auto is_baseline = [&](const CompareColumn& c) {
        return c.architecture == baseline->name() && c.variant.empty();
    };
    if (std::any_of(columns.begin(), columns.end(), is_baseline)) return true;
    const std::optional<std::string> why = why_not_runnable(input, baseline->name(), sets);
    if (why) log << "cncsim compare: no rows over " << baseline->name() << ", which cannot run it: " << *why << '\n';
    return !why;
}

}  // namespace cnc::sim
