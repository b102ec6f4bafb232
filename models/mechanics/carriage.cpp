#include "mechanics/carriage.hpp"
#include "common/sc_time.hpp"

#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

namespace {


void require_complete(const CarriageAxis& a, const char* axis) {
    if (a.step_event == nullptr || a.motor == nullptr || a.transmission == nullptr)
        throw BadInput("", std::string("carriage axis ") + axis + " needs a step event, a motor and a transmission");
}

double axis_mm(const CarriageAxis& a, TimePs t) { return a.transmission->carriage_mm(a.motor->shaft_angle_deg(t)); }

}  // namespace

Carriage::Carriage(const sc_core::sc_module_name& name, const CarriageConfig& cfg)
    : sc_core::sc_module(name), m_cfg(cfg) {
    require_complete(cfg.x, "x");
    require_complete(cfg.y, "y");
    SC_HAS_PROCESS(Carriage);
    SC_METHOD(sample);
    sensitive << *cfg.x.step_event << *cfg.y.step_event;
    dont_initialize();
}

geom::Vec2 Carriage::position() const {
    const TimePs t = now_ps();
    return m_cfg.origin + geom::Vec2{axis_mm(m_cfg.x, t), axis_mm(m_cfg.y, t)};
}

void Carriage::start_of_simulation() { sample(); }

void Carriage::sample() {
    const ToolSample s{now_ps(), position()};
    if (!m_samples.empty() && m_samples.back().t_ps == s.t_ps)
        m_samples.back() = s;
    else
        m_samples.push_back(s);
    m_x_mm = s.pos.x_mm;
    m_y_mm = s.pos.y_mm;
}

void Carriage::add_traces(sc_core::sc_trace_file* tf) const {
    sc_core::sc_trace(tf, m_x_mm, std::string(name()) + ".x_mm");
    sc_core::sc_trace(tf, m_y_mm, std::string(name()) + ".y_mm");
}

}  // namespace cnc::mech
