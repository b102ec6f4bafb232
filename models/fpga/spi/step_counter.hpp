// step_counter (not in seed 004): one per axis, counts the STEP pin's rising edges signed by DIR in a 32-bit register
// (timing in core/step_count_history.hpp: a rise at edge n is counted from edge n + 1). Wakes per STEP rise.
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/core/step_count_history.hpp"

namespace cnc::fpga {

class StepCountIf : public virtual sc_core::sc_interface {
public:
    // The count a register loading it at clock edge `edge` captures (called at that edge's time or later).
    [[nodiscard]] virtual std::int32_t value_at_edge(std::int64_t edge) const = 0;
};

class StepCounter : public sc_core::sc_module, public StepCountIf {
public:
    sc_core::sc_in<bool> step;
    sc_core::sc_in<bool> dir;

    StepCounter(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg);

    [[nodiscard]] std::int32_t value_at_edge(std::int64_t edge) const override { return m_history.value_at_edge(edge); }
    [[nodiscard]] std::int32_t count() const { return m_history.value(); }
    [[nodiscard]] std::uint64_t forward_rises() const { return m_history.forward_rises(); }
    [[nodiscard]] std::uint64_t reverse_rises() const { return m_history.reverse_rises(); }
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void on_step_rise();

    const ClockGrid m_clock;
    StepCountHistory m_history;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
