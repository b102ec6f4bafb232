// cmd_fifo (seed 004 §5.1.1 FIFO bus): frames of rate words from spi_slave to the per-axis pulse generators, as a
// hierarchical channel over core/cmd_fifo_core.hpp (register timing, full and empty behaviour documented there).
// Its default event fires one delta after a frame is accepted, so a generator can be `sensitive << fifo`; the
// applied event fires one delta after the read that completes a frame (laser_latch waits on it).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <systemc>
#include <vector>

#include "fpga/spi/core/cmd_fifo_core.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/core/spi_fpga_records.hpp"

namespace cnc::fpga {

struct FifoStatus {
    std::uint32_t level = 0;
    bool full = false;
    std::uint64_t drops_before = 0;  // frames dropped at edges before the queried one
};

class CmdFifoWriteIf : public virtual sc_core::sc_interface {
public:
    // Called at edge `edge`'s time; false when the frame was dropped (full).
    virtual bool push(std::int64_t edge, std::uint64_t seq, const spi::Command& command) = 0;
    [[nodiscard]] virtual FifoStatus status_at(std::int64_t edge) const = 0;
};

class CmdFifoReadIf : public virtual sc_core::sc_interface {
public:
    [[nodiscard]] virtual bool readable(std::size_t axis, std::int64_t edge) const = 0;
    virtual std::optional<FifoRead> read(std::size_t axis, std::int64_t edge) = 0;
};

// The frames every axis has loaded, in order (at most one per edge: the axes read in frame order).
class CmdFifoAppliedIf : public virtual sc_core::sc_interface {
public:
    [[nodiscard]] virtual const sc_core::sc_event& applied_event() const = 0;
    [[nodiscard]] virtual const AppliedFrame& last_applied() const = 0;
};

class CmdFifo : public sc_core::sc_module, public CmdFifoWriteIf, public CmdFifoReadIf, public CmdFifoAppliedIf {
public:
    CmdFifo(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t n_axes);

    bool push(std::int64_t edge, std::uint64_t seq, const spi::Command& command) override;
    [[nodiscard]] FifoStatus status_at(std::int64_t edge) const override;
    [[nodiscard]] bool readable(std::size_t axis, std::int64_t edge) const override;
    std::optional<FifoRead> read(std::size_t axis, std::int64_t edge) override;
    [[nodiscard]] const sc_core::sc_event& default_event() const override { return m_pushed; }
    [[nodiscard]] const sc_core::sc_event& applied_event() const override { return m_applied_event; }
    [[nodiscard]] const AppliedFrame& last_applied() const override { return m_last_applied; }
    // The applied-frame and push logs are for tests and benches: off, memory does not grow with a long job's frames.
    void keep_logs(bool on);
    [[nodiscard]] const std::vector<AppliedFrame>& applied() const { return m_applied; }

    [[nodiscard]] const CmdFifoCore& core() const { return m_core; }

private:
    const ClockGrid m_clock;
    CmdFifoCore m_core;
    sc_core::sc_event m_pushed;
    sc_core::sc_event m_applied_event;
    bool m_keep_applied_log = true;
    std::vector<AppliedFrame> m_applied;
    AppliedFrame m_last_applied;
};

}  // namespace cnc::fpga
