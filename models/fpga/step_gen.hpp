// step_gen (seed 000 §5.2.4, Π.5): IDLE/SETUP/DIR_WAIT/RUN/DONE STEP/DIR generator. On an accepted pkt_valid
// it builds the move's edge schedule (core/step_schedule.hpp) and wakes once per edge time; pkt_valid while not
// IDLE is logged as lost; cfg_valid latches the numerators (and the ramp's registers) only in IDLE.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <systemc>

#include "common/record_log.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/step_schedule.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class StepGen : public sc_core::sc_module {
public:
    sc_core::sc_in<std::int32_t> steps_x;
    sc_core::sc_in<std::int32_t> steps_y;
    sc_core::sc_in<std::uint16_t> feed_rate;
    sc_core::sc_in<bool> pkt_valid;
    sc_core::sc_in<std::uint32_t> numerator_x;
    sc_core::sc_in<std::uint32_t> numerator_y;
    sc_core::sc_in<std::uint32_t> ramp_accel;  // with fpga.ramp: the init packet's ramp registers (step_ramp.hpp)
    sc_core::sc_in<std::uint32_t> ramp_start;
    sc_core::sc_in<std::uint32_t> ramp_jerk;  // with the S-curve
    sc_core::sc_in<bool> cfg_valid;
    sc_core::sc_out<bool> dir_x;
    sc_core::sc_out<bool> step_x;
    sc_core::sc_out<bool> dir_y;
    sc_core::sc_out<bool> step_y;
    sc_core::sc_out<bool> busy;

    StepGen(const sc_core::sc_module_name& name, const FpgaConfig& cfg);

    struct Move {  // one pkt_valid seen by step_gen
        TimePs t_pkt_valid_ps = -1;
        bool accepted = false;
        StepPeriods periods;
        TimePs t_run_start_ps = -1;  // -1: ignored or zero-length
        TimePs t_busy_fall_ps = -1;
    };
    [[nodiscard]] const RecordLog<Move>& moves() const { return m_moves; }
    // The moves before index `end` have been read: they go.
    void drop_moves_before(std::size_t end) { m_moves.drop_before(end); }
    // True if the FSM is IDLE at clock edge `edge` (so it would accept pkt_valid / cfg_valid there).
    [[nodiscard]] bool idle_at_edge(std::int64_t edge) const { return edge >= m_idle_from; }
    // The e-stop (top.hpp): at edge `edge` STEP and busy go low and the FSM stops for good, the move it ran cut there.
    void halt_at(std::int64_t edge);
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void on_pkt_valid();
    void on_cfg_valid();
    void emit_edges();
    void fetch_next_edge();
    void notify_next_edge();
    void halt(std::int64_t edge);

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    std::uint32_t m_num_x;
    std::uint32_t m_num_y;
    std::uint32_t m_ramp_accel;
    std::uint32_t m_ramp_start;
    std::uint32_t m_ramp_jerk;
    bool m_dir_x = false;  // reset values
    bool m_dir_y = false;
    std::int64_t m_idle_from = 0;
    std::int64_t m_move_edge = 0;  // pkt_valid edge k of the running move
    std::optional<StepSchedule> m_schedule;
    std::optional<PinEdge> m_next;
    std::optional<std::int64_t> m_halt_edge;
    bool m_halted = false;
    sc_core::sc_event m_edge_due;
    RecordLog<Move> m_moves;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
