// pulse_gen (seed 004 §5.1.3 pulsegen): STEP and DIR of one axis from the rate words it reads from
// cmd_fifo, with the semantics of core/pulse_gen_core.hpp. Wakes only at its own pin edges, at a FIFO write
// (to schedule a read one clock later) and at read edges; never per clock.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <systemc>
#include <vector>

#include "fpga/spi/cmd_fifo.hpp"
#include "fpga/spi/core/pulse_gen_core.hpp"
#include "fpga/spi/core/spi_fpga_records.hpp"

namespace cnc::fpga {

class PulseGen : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> step;
    sc_core::sc_out<bool> dir;
    sc_core::sc_port<CmdFifoReadIf> fifo;

    // `axis`: which rate word of each frame this generator takes.
    PulseGen(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t axis);

    // The words applied and not taken yet; take_applied hands them over (a long job's would fill memory).
    [[nodiscard]] const std::vector<AppliedRate>& applied() const { return m_applied; }
    [[nodiscard]] std::vector<AppliedRate> take_applied();
    [[nodiscard]] std::uint64_t applied_count() const { return m_applied_count; }  // every word applied
    [[nodiscard]] std::uint64_t stretched() const { return m_stretched; }
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void on_push();
    void on_wake();
    void schedule();

    const std::size_t m_axis;
    const ClockGrid m_clock;
    PulseGenCore m_core;
    std::optional<std::int64_t> m_read_due;  // edge at which a readable entry should be considered
    sc_core::sc_event m_wake;
    std::vector<AppliedRate> m_applied;
    std::uint64_t m_applied_count = 0;
    std::uint64_t m_stretched = 0;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
