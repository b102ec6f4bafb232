// What compare checks before it starts a child: each column's scenario as its `cncsim run` reads it, so that bad
// input is reported once, by compare itself, and no child starts for a comparison that cannot be made.
#pragma once
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/compare.hpp"

namespace cnc::sim {

struct Scenario;

// What compare compares: its input as the user named it (a scenario, or a job and its machine), and how a child's
// `cncsim run` reads it with a list of --set overrides.
struct CompareInput {
    std::string name;
    std::function<Scenario(const std::vector<std::string>& overrides)> load;
};

// Why `cncsim run INPUT --set scenario.architecture=ARCH [--set ...]` would refuse its input: the input loaded
// with those overrides, then its job read and checked against the machine as that
// architecture takes it (load_job). nullopt when it would not.
[[nodiscard]] std::optional<std::string> why_not_runnable(const CompareInput& input, const std::string& architecture,
                                                          const std::vector<std::string>& sets);

// Throws cnc::BadInput when any column cannot run the scenario. Columns of architectures: the message once when they
// all give the same one, else each architecture with its own, and which of them could run it (for --arch). A
// variant's column: the first that cannot, named as `variants_from` gave it (--variant, or the scenario's
// compare.variants) with the reason (an unknown key lists the allowed ones).
void check_compare_columns(const CompareInput& input, const std::vector<CompareColumn>& columns,
                           const std::vector<std::string>& sets, const std::string& variants_from = "--variant");

// Whether compare runs the baseline (Architecture::baseline) beside `columns`, when none is it without a variant:
// not when it cannot run the scenario, which is then compared without the rows over it (said on `log`).
[[nodiscard]] bool baseline_runs(const CompareInput& input, const std::vector<CompareColumn>& columns,
                                 const std::vector<std::string>& sets, std::ostream& log);

}  // namespace cnc::sim
