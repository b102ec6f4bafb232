#include "mechanics/carriage.hpp"
#include "common/sc_time.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

namespace {

void require_complete(const CarriageAxis& a, const char* axis) {
    if (a.step_event == nullptr || a.drive == nullptr)
        throw BadInput("", std::string("carriage axis ") + axis + " needs a step event and a drive");
}

const CarriageConfig& checked(const CarriageConfig& cfg) {
    require_complete(cfg.x, "x");
    require_complete(cfg.y, "y");
    return cfg;
}

void write_position(PositionSignal& signal, double mm) {
    if (std::abs(mm - signal.read()) > kPositionSignalResolutionMm) signal.write(mm);
}

}  // namespace

Carriage::Carriage(const sc_core::sc_module_name& name, const CarriageConfig& cfg)
    : sc_core::sc_module(name), m_cfg(checked(cfg)),
      m_carriage_x_mm("carriage_x_mm", position().x_mm),
      m_carriage_y_mm("carriage_y_mm", position().y_mm) {
    SC_HAS_PROCESS(Carriage);
    SC_METHOD(on_step);
    sensitive << *cfg.x.step_event << *cfg.y.step_event;
    dont_initialize();
    SC_METHOD(on_period);
    sensitive << m_period_ev;
    dont_initialize();
}

void Carriage::on_step() {
    sample();
    if (m_cfg.sample_hz > 0.0 && !m_periodic_armed) {
        m_periodic_armed = true;
        m_period_ev.notify(sc_core::sc_time(1.0 / m_cfg.sample_hz, sc_core::SC_SEC));
    }
}

// Stops once both axes are at rest, so that a finished job leaves the kernel without events.
void Carriage::on_period() {
    sample();
    if (m_cfg.x.drive->at_rest() && m_cfg.y.drive->at_rest()) {
        m_periodic_armed = false;
        return;
    }
    m_period_ev.notify(sc_core::sc_time(1.0 / m_cfg.sample_hz, sc_core::SC_SEC));
}

geom::Vec2 Carriage::position() const {
    const TimePs t = now_ps();
    return m_cfg.origin + geom::Vec2{m_cfg.x.drive->carriage_mm(t), m_cfg.y.drive->carriage_mm(t)};
}

void Carriage::start_of_simulation() { sample(); }

std::vector<ToolSample> Carriage::take_samples_before(TimePs t_ps) {
    const auto end = std::lower_bound(m_samples.begin(), m_samples.end(), t_ps,
                                      [](const ToolSample& s, TimePs t) { return s.t_ps < t; });
    std::vector<ToolSample> taken(m_samples.begin(), end);
    m_samples.erase(m_samples.begin(), end);
    return taken;
}

void Carriage::sample() {
    const ToolSample s{now_ps(), position()};
    if (!m_samples.empty() && m_samples.back().t_ps == s.t_ps)
        m_samples.back() = s;
    else
        m_samples.push_back(s);
    write_position(m_carriage_x_mm, s.pos.x_mm);
    write_position(m_carriage_y_mm, s.pos.y_mm);
}

}  // namespace cnc::mech
