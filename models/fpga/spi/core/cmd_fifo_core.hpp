// cmd_fifo bookkeeping (seed 004 §5.1.1 FIFO bus between the SPI slave and the pulse generators): one write port
// (whole frames, written by the slave) and one read port per axis (each generator takes its own rate word
// of the oldest frame it has not read). An entry is freed once every axis has read it: from that edge the whole
// frame governs, and its laser bit goes to laser_latch (the read says so). Register timing:
//   a frame written at edge p is readable from edge p + 1;
//   the writer sees the level as of its edge x: frames written before x and not freed before x (a read at
//   edge r frees the slot for writes from edge r + 1);
//   full (level == depth) at the write edge: the new frame is dropped and counted; the FIFO keeps its frames;
//   empty for an axis: its generator keeps its last rate.
// Calls come in nondecreasing edge order (each at its own edge's time), which lets freed entries be forgotten.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "spi/core/spi_frame.hpp"

namespace cnc::fpga {

struct FifoRead {
    std::uint64_t seq = 0;  // the frame's number (SpiSlave's frame log index)
    spi::AxisRate rate;
    bool frame_applied = false;  // this was the frame's last unread word: every axis now runs on it
    bool laser_on = false;       // the frame's laser bit
};

struct FifoPushRecord {
    std::int64_t edge = 0;
    std::uint64_t seq = 0;
    bool dropped = false;
    std::uint32_t level_before = 0;  // frames held at the write edge
};

class CmdFifoCore {
public:
    CmdFifoCore(std::size_t depth, std::size_t n_axes);

    // false: full at `edge`, frame dropped.
    bool push(std::int64_t edge, std::uint64_t seq, const spi::Command& command);
    [[nodiscard]] bool readable(std::size_t axis, std::int64_t edge) const;
    // The axis's oldest unread rate word written before `edge`, marked read at `edge`.
    std::optional<FifoRead> read(std::size_t axis, std::int64_t edge);

    [[nodiscard]] std::uint32_t level_at(std::int64_t edge) const;
    [[nodiscard]] std::uint64_t drops_before(std::int64_t edge) const;
    // The push log is for tests and benches: off, memory does not grow with a long job's frames.
    void keep_push_log(bool on) { m_keep_log = on; }
    [[nodiscard]] const std::vector<FifoPushRecord>& pushes() const { return m_log; }
    [[nodiscard]] std::uint64_t dropped() const { return m_dropped; }
    [[nodiscard]] std::uint32_t max_level() const { return m_max_level; }
    [[nodiscard]] std::size_t depth() const { return m_depth; }

private:
    struct Entry {
        std::uint64_t index = 0;  // position in the stream of accepted frames
        std::uint64_t seq = 0;
        std::int64_t push_edge = 0;
        spi::Command command;
        std::vector<std::int64_t> read_edge;  // per axis, -1 while unread
    };
    [[nodiscard]] bool freed_before(const Entry& e, std::int64_t edge) const;
    void forget(std::int64_t edge);
    [[nodiscard]] const Entry* next_for(std::size_t axis) const;

    std::size_t m_depth;
    std::size_t m_axes;
    std::deque<Entry> m_entries;
    std::uint64_t m_next_index = 0;
    std::vector<std::uint64_t> m_read_index;  // per axis: index of the next entry to read
    bool m_keep_log = true;
    std::vector<FifoPushRecord> m_log;
    std::vector<std::int64_t> m_drop_edges;  // push edge of every dropped frame, in order (drops_before)
    std::uint64_t m_dropped = 0;
    std::uint32_t m_max_level = 0;
};

}  // namespace cnc::fpga
