// The spi-fpga host's servo thread (seed 004 §4.1: `addf motion-controller servo-thread` and the SPI driver's
// functions on one real-time thread): wakes at n * period + latency_n (core/latency.hpp), runs one period of
// core/servo_core.hpp with the reply of the previous transfer, and makes this period's full-duplex transfer
// through the SPI master. The host's computation takes no simulated time. Stops after the period in which
// the core reports the job done (no transfer then). Each frame carries the period's laser bit.
#pragma once
#include <optional>
#include <systemc>
#include <vector>

#include "common/units.hpp"
#include "host/core/planner/plan_feed.hpp"
#include "host/servo/core/latency.hpp"
#include "host/servo/core/servo_core.hpp"
#include "host/servo/core/servo_summary.hpp"
#include "spi/spi_master.hpp"

namespace cnc::host::servo {

class ServoThread : public sc_core::sc_module {
public:
    // `plan` and `master` must outlive the simulation.
    ServoThread(const sc_core::sc_module_name& name, const ServoConfig& cfg, planner::PlanFeed& plan, ServoJob job,
                spi::SpiMaster& master);

    [[nodiscard]] const ServoCore& core() const { return m_core; }
    // Every wake-up, one per log record, when kept (`--detail` lists them; the summary needs none).
    void keep_wakeups(bool keep) { m_keep_wakeups = keep; }
    [[nodiscard]] const std::vector<Wakeup>& wakeups() const { return m_wakeups; }
    [[nodiscard]] const ServoSummary& summary() const { return m_summary; }
    void drop_log_before(std::uint64_t n) { m_core.drop_log_before(n); }  // records read by everyone who needs them
    void drop_clock_before(TimePs t_ps, double tau_s) { m_core.drop_clock_before(t_ps, tau_s); }
    [[nodiscard]] bool finished() const { return m_t_done_ps.has_value(); }
    [[nodiscard]] std::optional<TimePs> t_done_ps() const { return m_t_done_ps; }
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void run();

    const ServoConfig m_cfg;
    ServoCore m_core;
    LatencyGenerator m_latency;
    spi::SpiMaster& m_master;
    bool m_keep_wakeups = true;
    std::vector<Wakeup> m_wakeups;
    ServoSummary m_summary;
    std::optional<TimePs> m_t_done_ps;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::host::servo
