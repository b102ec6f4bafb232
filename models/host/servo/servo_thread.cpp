#include "host/servo/servo_thread.hpp"

#include <limits>
#include <utility>

namespace cnc::host::servo {

ServoThread::ServoThread(const sc_core::sc_module_name& name, const ServoConfig& cfg, planner::PlanFeed& plan,
                         ServoJob job, spi::SpiMaster& master)
    : sc_module(name),
      m_cfg(cfg),
      m_core(m_cfg, plan, std::move(job)),
      m_latency(cfg.latency, cfg.seed),
      m_master(master) {
    SC_HAS_PROCESS(ServoThread);
    SC_THREAD(run);
}

void ServoThread::run() {
    std::optional<spi::Feedback> feedback;
    std::vector<std::uint8_t> reply;
    for (std::int64_t n = 0;; ++n) {
        const TimePs latency = m_latency.next();
        const TimePs wake = n * m_cfg.period_ps + latency;
        const auto now = static_cast<TimePs>(sc_core::sc_time_stamp().value());
        m_master.no_transfer_before(wake);  // a clocked model of the FPGA may run ahead to it
        if (wake > now) sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(wake - now)));
        ++m_activations;
        const Wakeup wakeup{static_cast<TimePs>(sc_core::sc_time_stamp().value()), latency};
        if (m_keep_wakeups) m_wakeups.push_back(wakeup);
        const PeriodRecord& rec = m_core.step(feedback);
        m_summary.add(rec, wakeup);
        if (rec.mode == PeriodMode::Done) {
            m_t_done_ps = wakeup.t_ps;
            m_master.no_transfer_before(std::numeric_limits<TimePs>::max());
            return;
        }
        spi::Command command{{}, rec.laser_on};
        for (const AxisPeriod& a : rec.axes) command.axes.push_back(a.word);
        m_master.transfer(spi::encode_command(command, m_cfg.min_period_cycles), reply);
        feedback = spi::decode_feedback(reply, kAxes);
    }
}

}  // namespace cnc::host::servo
