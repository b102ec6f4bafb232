// SPI mode 0 master (a Raspberry-Pi-class host, seed 004 §4.3.2): transfer() is called from the host's SC_THREAD and
// blocks for the transfer time of core/spi_timing.hpp while it drives SS low, toggles SCLK (one wake per SCLK
// edge), shifts MOSI on falling edges and samples MISO on rising edges, MSB first. MISO is sampled as it was
// just before the rising edge (a change at the same picosecond is not seen, the FPGA's clock convention).
// With trace_wires = false the pins stay idle and the bytes are exchanged through the `target` port at the
// SS fall and SS rise times instead; the slave then behaves exactly as over the wires.
// Only one thread may call transfer() (the pins have one writer). Bind ss to a signal that starts high.
#pragma once
#include <cstdint>
#include <optional>
#include <systemc>
#include <vector>

#include "common/units.hpp"
#include "spi/core/spi_bit_faults.hpp"
#include "spi/core/spi_timing.hpp"
#include "spi/spi_slave_if.hpp"

namespace cnc::spi {

class SpiMaster : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> sclk;
    sc_core::sc_out<bool> mosi;
    sc_core::sc_out<bool> ss;  // active low
    sc_core::sc_in<bool> miso;
    // Needed only when trace_wires is false.
    sc_core::sc_port<SpiSlaveIf, 1, sc_core::SC_ZERO_OR_MORE_BOUND> target;

    SpiMaster(const sc_core::sc_module_name& name, const SpiConfig& cfg);

    // Full duplex: shifts `out` and returns as many bytes in `in`. Waits first if the previous SS rise was less
    // than ss_idle_min ago. Returns at the SS rise.
    void transfer(const std::vector<std::uint8_t>& out, std::vector<std::uint8_t>& in);

    struct Transfer {
        TimePs t_ss_fall_ps = 0;
        TimePs t_ss_rise_ps = 0;
        std::size_t bits = 0;
    };
    // The transfer log is for tests and benches; a system turns it off before the simulation, so that memory does
    // not grow with a long job's transfers, and keeps the count.
    void keep_transfer_log(bool on) { m_keep_transfer_log = on; }
    [[nodiscard]] const std::vector<Transfer>& transfers() const { return m_transfers; }
    [[nodiscard]] std::uint64_t transfer_count() const { return m_transfer_count; }
    [[nodiscard]] TimePs ss_low_total_ps() const { return m_ss_low_total_ps; }  // link busy time
    [[nodiscard]] const SpiConfig& config() const { return m_cfg; }

    // Bit errors on the wires (spi/core/spi_bit_faults.hpp): the frames as the slave samples MOSI and as this
    // master samples MISO, whether the bits go over the wires or the transaction path.
    void set_bit_faults(double ber, std::uint64_t seed) { m_faults.emplace(ber, seed); }
    struct FaultStats {
        std::uint64_t mosi_frames_hit = 0;
        std::uint64_t mosi_bits_inverted = 0;
        std::uint64_t mosi_header_hit = 0;  // of the frames hit, those with a bit of byte 0 (the command) inverted
        std::uint64_t miso_frames_hit = 0;
        std::uint64_t miso_bits_inverted = 0;
    };
    [[nodiscard]] const FaultStats& fault_stats() const { return m_fault_stats; }

    // The caller starts no transfer before t_ps (a host thread that sleeps until then says so before it sleeps).
    void no_transfer_before(TimePs t_ps) { m_no_transfer_before_ps = t_ps; }
    // The earliest time SS, SCLK or MOSI may change, asked at the current time (>= now): the next edge of the
    // transfer under way, else the earliest start of the next one. A clocked model of the slave may run ahead to it.
    [[nodiscard]] TimePs pins_quiet_until() const;
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }
    void add_traces(sc_core::sc_trace_file* tf) const;

private:
    void end_of_elaboration() override;
    void wait_until(TimePs t_ps);
    void shift_on_wires(const std::vector<std::uint8_t>& out, std::vector<std::uint8_t>& in, TimePs t0);

    const SpiConfig m_cfg;
    TimePs m_idle_from_ps = 0;  // earliest next SS fall
    TimePs m_no_transfer_before_ps = 0;
    bool m_busy = false;
    TimePs m_next_pin_change_ps = 0;  // while busy
    bool m_keep_transfer_log = true;
    std::vector<Transfer> m_transfers;
    std::uint64_t m_transfer_count = 0;
    TimePs m_ss_low_total_ps = 0;
    std::uint64_t m_activations = 0;
    std::optional<SpiBitFaults> m_faults;
    FaultStats m_fault_stats;
};

}  // namespace cnc::spi
