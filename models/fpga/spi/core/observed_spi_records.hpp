// Seed 004's FPGA records (spi_fpga_records.hpp: the applied rate words, the counts) read off a clocked model of
// spi_fpga_top.v instead of logged by the event-driven blocks. The rules are the Verilog's: a FrameStart counts a
// frame (its sequence number: the frames started before it); a FrameEnd of a whole rates frame pushes it, or drops
// it when the FIFO is full; a generator's rd at an edge loads the word at its FIFO read port, frames in push order.
// The model runs ahead of the simulation time (up to the time its inputs are promised quiet), so every record
// carries its edge's time and a reader sees those at or before the time it gives.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "common/clock_grid.hpp"
#include "fpga/spi/core/spi_fpga_records.hpp"

namespace cnc::fpga {

// Values after one clock edge (spi_rtl_design.hpp's nets).
struct SpiNets {
    bool ss_fell = false;
    bool ss_rose = false;
    bool accepted = false;
    bool fifo_full = false;
    std::uint32_t fifo_level = 0;
    std::array<bool, 2> rd{};
    std::array<spi::AxisRate, 2> read_port{};      // the word each axis's FIFO read port shows
    std::array<std::uint32_t, 2> period_cycles{};  // each generator's governing period
    std::array<std::int32_t, 2> counts{};
};

class ObservedSpiRecords {
public:
    explicit ObservedSpiRecords(const ClockGrid& clock) : m_clock(clock) {
        m_snapshots.emplace_back(-1, SpiFpgaStats{});
    }

    // Edge n (> the last edge given; the edges in between changed none of the nets): `before` as after the edge
    // given last, `now` after edge n. `sim_now_ps`: the simulation time, up to which no reader will ask for less.
    void edge(std::int64_t n, const SpiNets& before, const SpiNets& now, TimePs sim_now_ps);

    // The words `axis` applied at or before t_ps and not taken yet; then they go.
    [[nodiscard]] std::vector<AppliedRate> take_applied(std::size_t axis, TimePs t_ps);
    // The counts as after the last edge at or before t_ps (>= the simulation time last given).
    [[nodiscard]] SpiFpgaStats stats(TimePs t_ps) const;

private:
    const ClockGrid m_clock;
    SpiFpgaStats m_stats;  // after the last edge given
    // The counts from the last edge at or before the simulation time on, one entry per edge that changed them.
    std::deque<std::pair<TimePs, SpiFpgaStats>> m_snapshots;
    std::deque<std::uint64_t> m_fifo_seq;       // per frame in the FIFO, oldest first: its sequence number
    std::array<std::size_t, 2> m_read_ahead{};  // per axis: the FIFO frames it has read
    std::array<std::deque<AppliedRate>, 2> m_applied;
};

}  // namespace cnc::fpga
