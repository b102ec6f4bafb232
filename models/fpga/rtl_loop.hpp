// What every FPGA shell running Verilog in the loop shares (rtl_top.hpp for seed 000, spi/rtl_spi_top.hpp for seed
// 004): one SystemC thread runs the verilated model in C++ batches, every clock edge up to the time before which
// the inputs cannot change (what the models driving them promise: inputs_quiet_until), writes each output change
// to its pin at its exact edge, and hands each edge that changed a watched value to the shell's records. An input
// changing before the promised time is a logic_error: the edges run ahead would have sampled the wrong level.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <systemc>
#include <utility>
#include <vector>

#include "common/clock_grid.hpp"
#include "fpga/timed_writer.hpp"
#include "rtl/plugin_build.hpp"
#include "rtl/plugin_spec.hpp"
#include "rtl/rtl_model.hpp"

namespace cnc::fpga {

class RtlLoop : public sc_core::sc_module {
public:
    struct Input {
        const sc_core::sc_in<bool>* pin;
        int input;  // its index in the spec's inputs
    };
    // A pin driven from an output port (its index in the spec's outputs) or from an observed net (its index in the
    // spec's observed list; a net the design lacks leaves the pin as it is).
    struct Output {
        sc_core::sc_out<bool>* pin;
        int port = -1;
        int net = -1;
    };
    struct Wiring {
        int reset_n = 0;  // the active-low synchronous reset input, low for edge 0 only
        std::vector<Input> inputs;
        std::vector<Output> outputs;
    };
    // Called with each edge n that changed a watched value (and edge 0, the reset state), in order.
    using EdgeHandler = std::function<void(std::int64_t n)>;

    // Loads the plug-in built from `spec`.
    RtlLoop(const sc_core::sc_module_name& name, const ClockGrid& clock, const rtl::PluginSpec& spec,
            const rtl::BuiltPlugin& plugin, Wiring wiring, EdgeHandler on_edge);

    // The earliest time any input may change, asked at the current time (>= now). Until given: now (one edge a
    // batch).
    void inputs_quiet_until(std::function<TimePs()> quiet_until_ps) { m_quiet_until = std::move(quiet_until_ps); }

    // The design changes no output until an input does, read off its nets by the shell. When it holds after the
    // edges run and nothing else in the simulation is pending, no input can change again: the loop stops clocking,
    // so that a design that never settles (a free-running counter) ends the run where the event-driven model does,
    // instead of being clocked to scenario.max_sim_s.
    void at_rest_when(std::function<bool()> at_rest) { m_at_rest = std::move(at_rest); }

    // Whether the design has the observed net.
    [[nodiscard]] bool has_net(std::size_t net) const { return m_observed_index[net] >= 0; }
    // An observed net after the edge handed over, and after the edge handed over before it (0 if the design lacks
    // the net).
    [[nodiscard]] std::uint64_t observed(std::size_t net) const { return watched(m_values, net); }
    [[nodiscard]] std::uint64_t observed_before(std::size_t net) const { return watched(m_before, net); }
    [[nodiscard]] std::uint64_t port(int output) const { return m_values[static_cast<std::size_t>(output)]; }
    // Clock edges the model has run (skipped ones of a settled design included).
    [[nodiscard]] std::int64_t cycles() const { return m_next_edge; }

private:
    void run_thread();
    void run_through(TimePs t_ps);  // every edge at or before t_ps, with the inputs as set; stops early when settled
    void edge(std::int64_t n);
    [[nodiscard]] bool input_changed(std::string& which) const;
    [[nodiscard]] std::uint64_t watched(const std::vector<std::uint64_t>& values, std::size_t net) const;

    const ClockGrid m_clock;
    std::unique_ptr<rtl::RtlModel> m_model;
    const Wiring m_wiring;
    const EdgeHandler m_on_edge;
    std::vector<int> m_observed_index;    // per spec.observed: its watched index, -1 if the design lacks it
    std::vector<std::uint64_t> m_values;  // the watched values after the last edge handed over
    std::vector<std::uint64_t> m_before;  // and after the one before it
    std::vector<std::uint64_t> m_read;    // scratch: the values after the edge just run
    std::vector<bool> m_levels;           // per wiring input: the level the model samples
    std::function<TimePs()> m_quiet_until;
    std::function<bool()> m_at_rest;
    std::int64_t m_next_edge = 0;
    TimePs m_promised_ps = 0;  // no input changes before this time
    TimedWriter m_writer;
};

}  // namespace cnc::fpga
