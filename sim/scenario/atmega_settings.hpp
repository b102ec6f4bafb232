// Scenario keys of the atmega architecture (seed 003), read into one struct by read_atmega_settings().
#pragma once
#include <filesystem>

#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct AtmegaSettings {};

void read_atmega_settings(KeyReader& r, AtmegaSettings& settings, const std::filesystem::path& base);

}  // namespace cnc::sim
