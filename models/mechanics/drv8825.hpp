// TI DRV8825 stepper driver: STEP/DIR indexer with microstepping, as the controller's pins see it.
//
// Steps are taken on STEP rising edges while enabled (nENBL low). DIR is sampled as the chip does, at the
// STEP rising edge: the level before the edge (a DIR change at the same instant is too late, and is flagged
// as a setup violation). MODE0..2 are read at each step, so each step has the size of the mode at that
// moment; the position is kept in the indexer's finest unit (1/32 step), so a mode change mid-run is exact
// (data sheet §8.3.5 behaviour: the indexer advances to the next valid state of the new mode).
// nSLEEP and nRESET are not modelled (tied inactive: awake, not in reset). The DECAY pin, current regulation
// and FAULT are outside the STEP/DIR interface and not modelled.
#pragma once
#include <cstdint>
#include <systemc>

#include "common/units.hpp"
#include "mechanics/core/drv8825_config.hpp"
#include "mechanics/core/drv8825_modes.hpp"
#include "mechanics/core/drv8825_timing.hpp"
#include "mechanics/core/motor.hpp"

namespace cnc::mech {

struct Drv8825Stats {
    std::int64_t steps = 0;             // steps that moved the indexer (net of strict-mode retractions)
    std::int64_t ignored_disabled = 0;  // STEP rises while nENBL was high
    std::int64_t ignored_short = 0;     // strict mode: pulses ignored or retracted for tWL / tWH
    std::int64_t lost_to_fault = 0;     // rises lost on the input (Drv8825Config::step_loss_rate)
    std::int64_t lost_net_steps = 0;    // the same, signed by the direction each would have stepped
};

class Drv8825 : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> step;
    sc_core::sc_in<bool> dir;
    sc_core::sc_in<bool> n_enbl;  // active low: tie to a false signal to keep the driver enabled
    sc_core::sc_in<bool> m0;
    sc_core::sc_in<bool> m1;
    sc_core::sc_in<bool> m2;

    Drv8825(const sc_core::sc_module_name& name, const Drv8825Config& cfg, StepperMotor& motor);

    // Indexer position in 1/32-step units (home = 0), signed by direction.
    [[nodiscard]] std::int64_t position_microsteps() const { return m_position; }
    [[nodiscard]] double position_full_steps() const {
        return static_cast<double>(m_position) / kIndexerUnitsPerFullStep;
    }
    [[nodiscard]] const Drv8825Stats& stats() const { return m_stats; }
    [[nodiscard]] const TimingStats& timing() const { return m_checker.stats(); }
    // Notified (delta) after every change of the commanded position, for position samplers.
    [[nodiscard]] const sc_core::sc_event& step_event() const { return m_step_ev; }
    // Notified (delta) after every change of nENBL, for position samplers (the currents, so the rotor, change).
    [[nodiscard]] const sc_core::sc_event& enable_event() const { return m_enable_ev; }
    void add_traces(sc_core::sc_trace_file* tf) const;

private:
    void start_of_simulation() override;
    void on_step();
    void on_dir();
    void on_enable();
    void move_to(TimePs t_ps, std::int64_t position);

    Drv8825Config m_cfg;
    StepperMotor& m_motor;
    Drv8825TimingChecker m_checker;
    std::int64_t m_position = 0;
    Drv8825Stats m_stats;
    sc_core::sc_event m_step_ev;
    sc_core::sc_event m_enable_ev;

    bool m_dir_level = false;   // DIR as last seen by on_dir
    bool m_dir_before = false;  // DIR before its last change
    TimePs m_dir_change_ps = -1;
    TimePs m_last_fall_ps = -1;
    bool m_pulse_moved = false;  // the current STEP pulse moved the indexer (strict mode may retract it)
    TimePs m_pulse_rise_ps = 0;
    std::int64_t m_position_before_pulse = 0;
    std::uint64_t m_fault_key = 0;
    std::uint64_t m_rises = 0;  // rising edges that would step: the fault draw's index
};

}  // namespace cnc::mech
