#include "mechanics/laser_head.hpp"
#include "common/sc_time.hpp"

namespace cnc::mech {

LaserHead::LaserHead(const sc_core::sc_module_name& name) : sc_core::sc_module(name), laser("laser") {
    SC_HAS_PROCESS(LaserHead);
    SC_METHOD(on_laser);
    sensitive << laser.value_changed();
    dont_initialize();
}

void LaserHead::start_of_simulation() {
    m_on = laser.read();
    m_on_since_ps = 0;
}

void LaserHead::on_laser() {
    const TimePs t = now_ps();
    const bool level = laser.read();
    if (level == m_on) return;
    if (level)
        m_on_since_ps = t;
    else
        m_on_total_ps += t - m_on_since_ps;
    m_on = level;
}

TimePs LaserHead::on_time_ps() const {
    return m_on_total_ps + (m_on ? now_ps() - m_on_since_ps : 0);
}

}  // namespace cnc::mech
