// The dynamic mechanics on threads of their own, one per axis (docs/mechanics.md, "The worker threads"). The carriage's models
// are open loop: no architecture reads the carriage back, only the metrics read its samples. So the simulation
// hands the workers its drivers' calls (a microstep, an enable change) and the instants of the steps as it makes
// them and runs on, while each axis is integrated behind it on a thread of its own (axis_worker.hpp), reading its
// carriage at the instants the tool sampler (tool_sampler.hpp) will want. The two axes' equations do not couple,
// and the sampler's rule makes what each axis is asked independent of the other, so the threads never wait for
// each other: an axis that moves while the other rests, or the second side of a square while the first still
// rings, runs beside the other. The simulation's thread then merges the readings through the same sampler,
// which decides, as the synchronous carriage's does, where the periodic samples stop; the samples and every
// figure of the axes are the same to the bit.
// The simulation's thread calls everything here; the axes belong to the workers until finish().
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "mechanics/core/axis_worker.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/tool_sampler.hpp"

namespace cnc::mech {

class MechanicsWorker {
public:
    // An axis: its motor, driven by its worker only until finish(), and the carriage drive it moves.
    struct Axis {
        StepperMotor* motor;
        const CarriageDrive* drive;
    };
    // `origin_mm`, `period_ps`: as the tool sampler's.
    MechanicsWorker(Axis x, Axis y, geom::Vec2 origin_mm, TimePs period_ps);
    ~MechanicsWorker();
    MechanicsWorker(const MechanicsWorker&) = delete;
    MechanicsWorker& operator=(const MechanicsWorker&) = delete;

    // The drivers' calls (StepperMotor), axis 0 = X, 1 = Y.
    void microstep(int axis, TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step);
    void enable(int axis, TimePs t_ps, bool enabled);
    // The sampler's events (ToolSampler::on_start, on_step, on_enable).
    void start(TimePs t_ps);
    void step(TimePs t_ps);
    void enable_changed(TimePs t_ps);

    // The simulation has reached t: every call before t has been made. The workers read the axes before t once
    // they get there, without the caller waiting. (A full batch of calls marks the time of its last one too.)
    void mark(TimePs t_ps);
    // The latest time before which the tool samples can be taken without waiting (marks t first).
    [[nodiscard]] TimePs ready_ps(TimePs t_ps);
    // The tool samples before t (marks t), once the workers have read the axes there: handed over and forgotten
    // there. A caller that marked t a while before (a slice of the simulation) seldom waits. Rethrows what a
    // worker threw.
    [[nodiscard]] std::vector<ToolSample> take_before(TimePs t_ps);

    struct End {
        std::optional<TimePs> last_periodic_ps;  // the last periodic sample taken, if any
        bool periodic_past_bound = false;        // an axis still moved: periodic samples were due after the bound
    };
    // The simulation has ended: the periodic samples up to the bound (before it, or also at it with
    // `bound_inclusive`) are taken, the threads end, and the axes are the caller's again. Rethrows what a worker
    // threw. Once only.
    End finish(TimePs bound_ps, bool bound_inclusive);
    // After finish(): every sample not handed over.
    [[nodiscard]] const std::vector<ToolSample>& samples_left() const { return m_sampler.samples(); }

private:
    using Command = MechanicsCommand;
    using Kind = MechanicsCommand::Kind;

    // An axis as its worker read it, for the merging sampler: the readings in order, and between them, at the
    // periodic grid times the axis rested through, where it came to rest.
    class Replay : public CarriageDrive {
    public:
        // The sampler's next query is at a periodic grid time (else at the start or a step).
        void expect(bool periodic) { m_periodic = periodic; }
        [[nodiscard]] double carriage_mm(TimePs t_ps) const override;
        [[nodiscard]] bool at_rest() const override { return m_at_rest; }
        // Forgets the readings the sampler has had.
        void drop_used();

        std::vector<AxisReading> readings;

    private:
        mutable std::size_t m_next = 0;
        mutable bool m_at_rest = false;
        mutable double m_mm = 0.0;
        bool m_periodic = false;
    };

    void push(const Command& c);
    void flush();
    // Merges the readings through the sampler up to the first mark at or after t (or all that were marked).
    void merge_until(TimePs t_ps);
    void merge(const Command& c);
    // Takes the periodic samples due before t (or also at t).
    void periodic_until(TimePs t_ps, bool inclusive);

    Replay m_replay[2];
    ToolSampler m_sampler;
    std::unique_ptr<AxisWorker> m_workers[2];
    // Commands not yet handed to the workers (a batch at a time, so their locks are rare).
    std::vector<Command> m_batch;
    // The sampler's commands (and marks) not yet merged, and how many marks have been merged.
    std::vector<Command> m_to_merge;
    std::int64_t m_marks_merged = 0;
    TimePs m_merged_ps = 0;  // the last mark merged
    TimePs m_marked_ps = -1;
    std::optional<TimePs> m_next_periodic_ps;
    End m_end;
    bool m_finished = false;
};

}  // namespace cnc::mech
