// The dynamic mechanics on a thread of their own (docs/mechanics.md, "Speed"). The carriage's models are open
// loop: no architecture reads the carriage back, only the metrics read its samples. So the simulation hands the
// worker its drivers' calls (a microstep, an enable change) and the instants of the steps as it makes them and
// runs on, while the worker integrates the axes behind it on the other core and takes the tool samples
// (tool_sampler.hpp), periodic ones included: whether those go on depends on the axes' rest, which only the
// integration knows. The worker makes the same calls in the same order as the synchronous carriage (the
// periodic sample of an instant before its steps, as the SystemC kernel orders them), so the samples and every
// figure of the axes are the same to the bit.
// The simulation's thread calls everything here; the axes and the sampler belong to the worker until finish().
#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/tool_sampler.hpp"

namespace cnc::mech {

class MechanicsWorker {
public:
    // `x`, `y`: the axes' motors, driven by the worker only until finish(); `sampler` reads the same axes.
    MechanicsWorker(StepperMotor& x, StepperMotor& y, ToolSampler& sampler);
    ~MechanicsWorker();
    MechanicsWorker(const MechanicsWorker&) = delete;
    MechanicsWorker& operator=(const MechanicsWorker&) = delete;

    // The drivers' calls (StepperMotor), axis 0 = X, 1 = Y.
    void microstep(int axis, TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step);
    void enable(int axis, TimePs t_ps, bool enabled);
    // The sampler's events (ToolSampler::on_start, on_step).
    void start(TimePs t_ps);
    void step(TimePs t_ps);

    // The simulation has reached t: every call before t has been made. The worker takes the samples before t
    // once it gets there, without the caller waiting.
    void mark(TimePs t_ps);
    // The tool samples before t (marks t), once the worker has taken them: handed over and forgotten there. A
    // caller that marked t a while before (a slice of the simulation) seldom waits. Rethrows what the worker threw.
    [[nodiscard]] std::vector<ToolSample> take_before(TimePs t_ps);

    struct End {
        std::optional<TimePs> last_periodic_ps;  // the last periodic sample taken, if any
        bool periodic_past_bound = false;         // an axis still moved: periodic samples were due after the bound
    };
    // The simulation has ended: the periodic samples up to the bound (before it, or also at it with
    // `bound_inclusive`) are taken, the thread ends, and the axes are the caller's again. Rethrows what the
    // worker threw. Once only.
    End finish(TimePs bound_ps, bool bound_inclusive);
    // After finish(): every sample not handed over.
    [[nodiscard]] const std::vector<ToolSample>& samples_left() const { return m_ready; }

private:
    enum class Kind : std::uint8_t { Microstep, Enable, Start, Step, Sync, End };
    struct Command {
        Kind kind;
        std::int8_t axis;
        bool flag;  // Enable: enabled; End: bound inclusive
        int microsteps;
        TimePs t_ps;
        std::int64_t index;
    };

    void push(const Command& c);
    void flush();
    void run();
    void execute(const Command& c);
    // Takes the periodic samples due before t (or also at t).
    void periodic_until(TimePs t_ps, bool inclusive);
    // Hands the sampler's samples before t over to the simulation's side.
    void publish(TimePs before_ps);

    StepperMotor* m_motors[2];
    ToolSampler& m_sampler;

    // The simulation's side: commands not yet handed over (a batch at a time, so the lock is rare).
    std::vector<Command> m_batch;
    TimePs m_marked_ps = -1;
    // Shared, under m_mutex.
    std::mutex m_mutex;
    std::condition_variable m_cv_work;
    std::condition_variable m_cv_synced;
    std::vector<Command> m_queue;
    std::vector<ToolSample> m_ready;  // samples final and not yet handed over
    TimePs m_synced_ps = -1;           // every sample before this is in m_ready
    std::exception_ptr m_error;
    // The worker's side (m_end the caller's after the thread has ended).
    std::optional<TimePs> m_next_periodic_ps;
    End m_end;

    std::thread m_thread;
    bool m_finished = false;
};

}  // namespace cnc::mech
