// The architectures cncsim knows (registry.hpp), as the scenario reader, the job checks, `compare` and the plots
// look them up: by name, in the registry's order.
#pragma once
#include <string>
#include <vector>

#include "architectures/architecture.hpp"

namespace cnc::sim {

[[nodiscard]] const std::vector<const Architecture*>& architectures();
[[nodiscard]] std::vector<std::string> architecture_names();
// Every name, comma-separated, for messages.
[[nodiscard]] std::string architecture_list();
// The architecture the others are measured against (Architecture::baseline); null when none is.
[[nodiscard]] const Architecture* baseline_architecture();
// BadInput at `where` naming the allowed architectures when `name` is not one of them.
[[nodiscard]] const Architecture& find_architecture(const std::string& name, const std::string& where);

}  // namespace cnc::sim
