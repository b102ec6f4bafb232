// The laser module's TTL enable input (active high; seed 000 §5.2.5 laser_ctrl drives it): its state and total
// on-time. Power modulation is not part of the seed (ON/OFF only, seed 000 §5.2.5). The on/off history is the
// probes' (the metrics and the VCD record the pin): kept here it would grow with the job.
#pragma once
#include <systemc>

#include "common/units.hpp"

namespace cnc::mech {

class LaserHead : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> laser;

    explicit LaserHead(const sc_core::sc_module_name& name);

    [[nodiscard]] bool is_on() const { return m_on; }
    // Total time on from t = 0 up to now.
    [[nodiscard]] TimePs on_time_ps() const;

private:
    void start_of_simulation() override;
    void on_laser();

    bool m_on = false;
    TimePs m_on_since_ps = 0;
    TimePs m_on_total_ps = 0;  // closed on-intervals
};

}  // namespace cnc::mech
