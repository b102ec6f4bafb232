#include "scenario/spi_fpga_settings.hpp"

namespace cnc::sim {

void read_spi_fpga_settings(KeyReader&, SpiFpgaSettings&, const std::filesystem::path&) {}

}  // namespace cnc::sim
