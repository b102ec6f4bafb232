#include "mechanics/core/tool_sampler.hpp"

namespace cnc::mech {

ToolSampler::ToolSampler(const CarriageDrive& x, const CarriageDrive& y, geom::Vec2 origin_mm, TimePs period_ps)
    : m_x(x), m_y(y), m_origin_mm(origin_mm), m_period_ps(period_ps) {}

std::optional<TimePs> ToolSampler::on_start(TimePs t_ps) {
    sample(t_ps);
    return start_periodic(t_ps);
}

std::optional<TimePs> ToolSampler::on_step(TimePs t_ps) {
    sample(t_ps);
    return start_periodic(t_ps);
}

std::optional<TimePs> ToolSampler::on_enable(TimePs t_ps) {
    return start_periodic(t_ps);
}

std::optional<TimePs> ToolSampler::start_periodic(TimePs t_ps) {
    if (m_period_ps <= 0 || m_periodic) return std::nullopt;
    m_periodic = true;
    return first_edge_after(t_ps, m_period_ps) * m_period_ps;
}

std::optional<TimePs> ToolSampler::on_period(TimePs t_ps) {
    sample(t_ps);
    if (m_x.at_rest() && m_y.at_rest()) {
        m_periodic = false;
        return std::nullopt;
    }
    return t_ps + m_period_ps;
}

std::vector<ToolSample> ToolSampler::take_before(TimePs t_ps) {
    return take_samples_before(m_samples, t_ps);
}

void ToolSampler::sample(TimePs t_ps) {
    const ToolSample s{t_ps, m_origin_mm + geom::Vec2{m_x.carriage_mm(t_ps), m_y.carriage_mm(t_ps)}};
    if (!m_samples.empty() && m_samples.back().t_ps == s.t_ps)
        m_samples.back() = s;
    else
        m_samples.push_back(s);
}

}  // namespace cnc::mech
