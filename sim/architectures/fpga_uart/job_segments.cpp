#include "architectures/fpga_uart/job_segments.hpp"

#include <vector>

#include "architectures/fpga_uart/fpga_uart_settings.hpp"

namespace cnc::sim {

JobSegments::JobSegments(const Scenario& s, const Job& job) : m_job(job) {
    if (!job.program) return;
    m_moves = std::make_unique<host::GcodeStream>(s.job_path, s.interpreter, false);
    m_cam.emplace(s.job_path, s.machine, s.settings<FpgaUartSettings>().cam);
    m_waits.emplace(job.program->waits);
}

std::optional<MadeSegment> JobSegments::next() {
    if (!m_moves) {
        if (m_next == m_job.steps_file.size()) return std::nullopt;
        return MadeSegment{m_job.steps_file[m_next++], std::nullopt, 0.0, {}};
    }
    std::vector<host::MotionSegment> made;
    while (m_pending.empty()) {
        const std::optional<host::ProgrammedMove> move = m_moves->next();
        if (!move) return std::nullopt;
        made.clear();
        m_cam->add(*move, m_next, made);
        if (made.empty()) m_unstepped.push_back({static_cast<int>(m_next), *move});
        ++m_next;
        m_pending.assign(made.begin(), made.end());
        m_move = move;
    }
    MadeSegment out{m_pending.front(), m_move, m_waits->before_unit(static_cast<std::size_t>(m_pending.front().move)),
                    std::move(m_unstepped)};
    m_unstepped.clear();
    m_pending.pop_front();
    return out;
}

double JobSegments::wait_after_last_s() {
    return m_waits ? m_waits->after_last() : 0.0;
}

}  // namespace cnc::sim
