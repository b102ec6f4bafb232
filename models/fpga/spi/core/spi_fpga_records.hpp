// What the spi-fpga FPGA logs for reports: frames seen by the SPI slave, rate words applied per axis, and the
// frames applied as a whole (with their laser bit), and the counts the report reads.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/units.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::fpga {

struct SlaveFrameRecord {
    std::uint64_t seq = 0;     // index in SpiSlave::frames()
    TimePs t_snapshot_ps = 0;  // FrameStart edge: counters and status captured for the reply
    TimePs t_end_ps = 0;       // FrameEnd edge: pushed to the FIFO (or rejected) here
    std::size_t mosi_bits = 0;
    bool accepted = false;            // whole frame with the kCmdRates header
    bool dropped = false;             // accepted but the FIFO was full
    std::vector<std::uint8_t> reply;  // bytes loaded for MISO (the words are in the generators' applied logs)
};

struct AppliedRate {
    std::int64_t edge = 0;  // the word governs from this edge
    TimePs t_ps = 0;
    std::uint64_t seq = 0;  // frame it came from
    spi::AxisRate rate;
    bool stretched = false;  // period below pulse + 1, raised to it
};

// A frame whose rate words every axis has loaded: it governs from this edge, and laser_latch takes its laser bit.
struct AppliedFrame {
    std::int64_t edge = 0;
    TimePs t_ps = 0;
    std::uint64_t seq = 0;
    bool laser_on = false;
};

// The FPGA's counts so far (report: "fpga").
struct SpiFpgaStats {
    std::uint64_t frames = 0;           // SS falls the slave has seen
    std::uint64_t frames_accepted = 0;  // whole frames with the rates command, dropped ones included
    std::uint64_t fifo_drops = 0;       // accepted frames the full FIFO dropped
    std::uint32_t fifo_max_level = 0;   // the most frames the FIFO has held
    std::uint64_t stretched_words = 0;  // both axes' words raised to the shortest period
    std::array<std::uint64_t, 2> words_applied{};  // per axis
    std::array<std::int32_t, 2> counts{};          // the step counters' registers
};

}  // namespace cnc::fpga
