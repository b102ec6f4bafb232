// Seed 000's FPGA as the system around it sees it, whichever model runs it: the event-driven blocks (top.hpp) or
// the Verilog of rtl/ verilated and clocked in the loop (rtl_top.hpp). top.v's pins, four internal strobes
// exported for tracing, and the records the reports read (fpga_records.hpp). Every output must be bound (tx to a
// signal that starts high: the line idles high).
#pragma once
#include <cstddef>
#include <systemc>
#include <vector>

#include "common/clock_grid.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/fpga_records.hpp"

namespace cnc::fpga {

class Board : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> rx;       // GPIO_0[0], from CP2102 TXD
    sc_core::sc_out<bool> tx;      // GPIO_0[1], to CP2102 RXD
    sc_core::sc_out<bool> dir_x;   // GPIO_0[2]
    sc_core::sc_out<bool> step_x;  // GPIO_0[3]
    sc_core::sc_out<bool> dir_y;   // GPIO_0[4]
    sc_core::sc_out<bool> step_y;  // GPIO_0[5]
    sc_core::sc_out<bool> laser;   // GPIO_0[6]
    sc_core::sc_out<bool> busy;    // internal nets exported for tracing (one-clock pulses except busy)
    sc_core::sc_out<bool> pkt_valid;
    sc_core::sc_out<bool> cfg_valid;
    sc_core::sc_out<bool> rx_valid;
    sc_core::sc_out<bool> tx_start;
    // Our safety inputs (fpga.estop, fpga.interlock), active high; tied low inside unless the option gives them.
    sc_core::sc_in<bool> estop;
    sc_core::sc_in<bool> lid_open;

    // One record per pkt_valid step_gen has seen, the dropped ones included, in order; record i while not dropped.
    [[nodiscard]] virtual std::size_t packet_count() const = 0;
    [[nodiscard]] virtual PacketRecord packet(std::size_t i) const = 0;
    // Every reader has read the records before index `end`: they go.
    virtual void drop_packets_before(std::size_t end) = 0;
    [[nodiscard]] virtual const std::vector<InitRecord>& inits() const = 0;
    [[nodiscard]] virtual FpgaStats stats() const = 0;
    // False when the records are read off the pins alone (a design without top.v's nets: rtl_top.hpp).
    [[nodiscard]] virtual bool records_from_nets() const { return true; }
    // The edges of CLOCK_50 as this board's oscillator makes them.
    [[nodiscard]] virtual const ClockGrid& clock() const = 0;

protected:
    explicit Board(const sc_core::sc_module_name& name)
        : sc_module(name),
          rx("rx"),
          tx("tx"),
          dir_x("dir_x"),
          step_x("step_x"),
          dir_y("dir_y"),
          step_y("step_y"),
          laser("laser"),
          busy("busy"),
          pkt_valid("pkt_valid"),
          cfg_valid("cfg_valid"),
          rx_valid("rx_valid"),
          tx_start("tx_start"),
          estop("estop"),
          lid_open("lid_open") {}

    // Binds the safety inputs `cfg` leaves out to a low signal.
    void tie_unused_inputs(const FpgaConfig& cfg) {
        if (!cfg.estop_input) estop(m_tied_low);
        if (!cfg.interlock_input) lid_open(m_tied_low);
    }

private:
    sc_core::sc_signal<bool> m_tied_low{"tied_low", false};
};

}  // namespace cnc::fpga
