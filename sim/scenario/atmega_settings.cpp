#include "scenario/atmega_settings.hpp"

namespace cnc::sim {

void read_atmega_settings(KeyReader&, AtmegaSettings&, const std::filesystem::path&) {}

}  // namespace cnc::sim
