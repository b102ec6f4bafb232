// Seed 004's FPGA as the system around it sees it, whichever model runs it: the event-driven blocks
// (spi_fpga_top.hpp) or the Verilog of rtl/spi_fpga_top.v verilated and clocked in the loop (rtl_spi_top.hpp).
// spi_fpga_top.v's pins and what the spi-fpga report and its rate segments read: the applied rate words per axis
// and the counts. Bind ss to a signal that starts high; every output must be bound.
#pragma once
#include <cstddef>
#include <cstdint>
#include <systemc>
#include <vector>

#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/core/spi_fpga_records.hpp"

namespace cnc::fpga {

class SpiBoard : public sc_core::sc_module {
public:
    static constexpr std::size_t kAxes = 2;

    sc_core::sc_in<bool> sclk;
    sc_core::sc_in<bool> mosi;
    sc_core::sc_in<bool> ss;  // active low
    sc_core::sc_out<bool> miso;
    sc_core::sc_out<bool> step_x;
    sc_core::sc_out<bool> dir_x;
    sc_core::sc_out<bool> step_y;
    sc_core::sc_out<bool> dir_y;
    sc_core::sc_out<bool> laser;

    [[nodiscard]] virtual const SpiFpgaConfig& config() const = 0;
    // The words `axis` has applied and not handed over yet, in order; then they go.
    [[nodiscard]] virtual std::vector<AppliedRate> take_applied(std::size_t axis) = 0;
    [[nodiscard]] virtual SpiFpgaStats stats() const = 0;

protected:
    explicit SpiBoard(const sc_core::sc_module_name& name)
        : sc_module(name),
          sclk("sclk"),
          mosi("mosi"),
          ss("ss"),
          miso("miso"),
          step_x("step_x"),
          dir_x("dir_x"),
          step_y("step_y"),
          dir_y("dir_y"),
          laser("laser") {}
};

}  // namespace cnc::fpga
