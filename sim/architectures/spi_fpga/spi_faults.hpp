// Bit errors on the SPI wires (faults.spi_ber) as the report shows them: the frames each way that a bit error hit;
// of those to the FPGA, the ones its command check refused (a bit of the 0x52 header changed) and the ones it ran
// with changed rate words or laser bit, which nothing on the link notices (the servo loop then corrects the
// position it reads back from the step counters); the replies hit change what the servo loop reads.
#pragma once
#include "fpga/spi/core/spi_fpga_records.hpp"
#include "run/arch_run.hpp"
#include "scenario/fault_settings.hpp"
#include "spi/spi_master.hpp"

namespace cnc::sim {

void report_spi_faults(const FaultSettings& f, const spi::SpiMaster& master, const fpga::SpiFpgaStats& fpga,
                       ArchRun& run);

}  // namespace cnc::sim
