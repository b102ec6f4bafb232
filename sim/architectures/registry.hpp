// Every architecture cncsim runs, in the order it lists them and `compare` runs them: the one place that names
// them all. An entry is an architecture's folder's Entry: its description (architecture(), without SystemC, for the
// scenario reader, the job checks and `compare`) and its run (run(), the elaborated system: run/controller.hpp).
#pragma once
#include "architectures/atmega/atmega.hpp"
#include "architectures/fpga_uart/fpga_uart.hpp"
#include "architectures/grbl/grbl.hpp"
#include "architectures/ideal/ideal.hpp"
#include "architectures/lathe_sync/lathe_sync.hpp"
#include "architectures/spi_fpga/spi_fpga.hpp"

namespace cnc::sim {

template <typename... Entries>
struct EntryList {};

using Registry =
    EntryList<fpga_uart::Entry, atmega::Entry, spi_fpga::Entry, lathe_sync::Entry, grbl::Entry, ideal::Entry>;

}  // namespace cnc::sim
