// The XY carriage: each axis is a drive (an ideal motor on a rigid transmission, or a dynamic axis model); the
// tool position is sampled as tool_sampler.hpp says (at every step event and, with sample_hz > 0, periodically
// while an axis moves, from the start, a step or an enable change on). At each sample the position goes to the
// real-valued signals carriage_x_mm / carriage_y_mm (what the VCD traces) when it has moved by more than
// kPositionSignalResolutionMm since the value they hold.
// With `worker_thread` each axis runs on a thread of its own (mechanics_worker.hpp): the drivers reach the motors
// through WorkerMotor, the carriage hands the workers the instants of the steps and enable changes, and the
// samples come from the workers' readings; the position signals are then not written (a run that traces them
// keeps the axes on its thread).
#pragma once
#include <memory>
#include <optional>
#include <systemc>
#include <vector>

#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/mechanics_worker.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/tool_sampler.hpp"

namespace cnc::mech {

struct CarriageAxis {
    const sc_core::sc_event* step_event = nullptr;  // the axis driver's step_event()
    const CarriageDrive* drive = nullptr;
    StepperMotor* motor = nullptr;  // with worker_thread: the motor the worker drives (the driver has a WorkerMotor)
    const sc_core::sc_event* enable_event = nullptr;  // the axis driver's enable_event(), if it has one
};

struct CarriageConfig {
    CarriageAxis x;
    CarriageAxis y;
    geom::Vec2 origin{};     // tool position (machine mm) with both shafts at 0 deg
    double sample_hz = 0.0;  // periodic samples while an axis moves; 0: at step events only
    bool worker_thread = false;
};

using ToolSample = cnc::ToolSample;

// 0.1 um: a hundredth of the finest microstep of the shipped machines (1/32 step on a 40 mm/rev belt,
// 6.25 um), well below what a contour error of um needs, and it keeps a carriage settling by nm from writing
// a VCD value at every sample.
inline constexpr double kPositionSignalResolutionMm = 1e-4;
// Written by the step and the periodic sample processes.
using PositionSignal = sc_core::sc_signal<double, sc_core::SC_MANY_WRITERS>;

class Carriage : public sc_core::sc_module {
public:
    Carriage(const sc_core::sc_module_name& name, const CarriageConfig& cfg);

    // Tool position now (not with the worker thread).
    [[nodiscard]] geom::Vec2 position() const;
    // Every sample not handed over (with the worker thread: after finish()).
    [[nodiscard]] const std::vector<ToolSample>& samples() const;
    // Hands over the samples taken before t_ps and forgets them, for metrics that measure as the run goes (a
    // sample at t_ps or later may still be overwritten by a step at its instant, so it stays). t_ps no later than
    // the simulation's time.
    [[nodiscard]] std::vector<ToolSample> take_samples_before(TimePs t_ps);
    // The latest time before which take_samples_before() need not wait (with the worker thread: for the workers
    // to get there; without, now).
    [[nodiscard]] TimePs samples_ready_ps();
    // The simulation has stopped. With the worker thread: the periodic samples up to the bound (before it, or also
    // at it with `bound_inclusive`) are taken, the thread ends and the axes may be read again; what it says of the
    // periodic samples. Nothing without the worker thread (the kernel took them).
    std::optional<MechanicsWorker::End> finish(TimePs bound_ps, bool bound_inclusive);
    // With the worker thread: where the drivers' WorkerMotors send their calls.
    [[nodiscard]] MechanicsWorker& worker() { return *m_worker; }
    // The tool position in machine mm, per axis, updated at the samples (resolution above).
    [[nodiscard]] const PositionSignal& carriage_x_mm() const { return m_carriage_x_mm; }
    [[nodiscard]] const PositionSignal& carriage_y_mm() const { return m_carriage_y_mm; }

private:
    void start_of_simulation() override;
    void on_step();
    void on_enable();
    // An event of the sampler's (the start, a step, an enable change): to the worker, or to the sampler, whose
    // periodic samples it may start.
    void on_event(void (MechanicsWorker::*to_worker)(TimePs), std::optional<TimePs> (ToolSampler::*to_sampler)(TimePs));
    void on_period();
    void write_positions();

    CarriageConfig m_cfg;
    ToolSampler m_sampler;
    std::unique_ptr<MechanicsWorker> m_worker;
    sc_core::sc_event m_period_ev;
    PositionSignal m_carriage_x_mm;
    PositionSignal m_carriage_y_mm;
};

// A driver's motor when the axes run on the worker thread: its calls go to the worker, for the axis's motor.
class WorkerMotor : public StepperMotor {
public:
    WorkerMotor(Carriage& carriage, int axis) : m_carriage(carriage), m_axis(axis) {}
    void on_microstep(TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) override {
        m_carriage.worker().microstep(m_axis, t_ps, microstep_index, microsteps_per_full_step);
    }
    void on_enable(TimePs t_ps, bool enabled) override { m_carriage.worker().enable(m_axis, t_ps, enabled); }
    // The worker's axis is not to be read while it runs (the carriage's samples are).
    [[nodiscard]] double shaft_angle_deg(TimePs t_ps) const override;

private:
    Carriage& m_carriage;
    int m_axis;
};

}  // namespace cnc::mech
