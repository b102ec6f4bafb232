// Scenario keys of the spi-fpga architecture (seed 004), read into one struct by read_spi_fpga_settings().
#pragma once
#include <filesystem>

#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct SpiFpgaSettings {};

void read_spi_fpga_settings(KeyReader& r, SpiFpgaSettings& settings, const std::filesystem::path& base);

}  // namespace cnc::sim
