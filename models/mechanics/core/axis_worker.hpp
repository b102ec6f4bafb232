// One axis of the dynamic mechanics on a thread of its own (mechanics_worker.hpp). It gets every call the
// simulation makes, in order: it makes its axis's driver calls and reads its axis's carriage at the instants the
// tool sampler (tool_sampler.hpp) samples: the start, every step of either axis, and every periodic grid time
// at which this axis is not at rest. The sampler takes those whatever the other axis does (a grid time is
// skipped only once both axes rest), so this thread needs nothing from the other one; a grid time at which this
// axis rests is not read (a resting axis changes nothing when asked: dynamic_axis.hpp), and the merging side
// takes its position from the last reading.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "common/units.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/motor.hpp"

namespace cnc::mech {

// A call of the simulation, as the axis workers and the merging side see it.
struct MechanicsCommand {
    enum class Kind : std::uint8_t { Microstep, Enable, Start, Step, EnableChanged, Sync, End };
    Kind kind;
    std::int8_t axis;  // Microstep, Enable: 0 = X, 1 = Y
    bool flag;         // Enable: enabled; End: bound inclusive
    int microsteps;    // Microstep: per full step
    TimePs t_ps;
    std::int64_t index;  // Microstep: the indexer position
};

// The carriage of one axis at one of the sampler's instants.
struct AxisReading {
    TimePs t_ps;
    bool periodic;  // at a periodic grid time (else at the start or a step)
    bool at_rest;   // the axis is at rest after it (CarriageDrive::at_rest)
    double carriage_mm;
};

class AxisWorker {
public:
    // `axis`: 0 = X, 1 = Y; `motor` and `drive`: the axis, driven by this thread only until join();
    // `period_ps`: the periodic samples' grid (0: none).
    AxisWorker(int axis, StepperMotor& motor, const CarriageDrive& drive, TimePs period_ps);
    ~AxisWorker();
    AxisWorker(const AxisWorker&) = delete;
    AxisWorker& operator=(const AxisWorker&) = delete;

    // Hands over calls, in order; a Sync or End makes the readings up to it available.
    void push(const std::vector<MechanicsCommand>& commands);
    // How many Syncs the readings are available for (without waiting).
    [[nodiscard]] std::int64_t syncs_published();
    // Blocks until the readings up to the `syncs`-th Sync (or the End) are available, and moves them onto `to`.
    // Rethrows what the thread threw.
    void take_readings(std::int64_t syncs, std::vector<AxisReading>& to);
    // Blocks until the End has been handled and the thread has ended; the axis is the caller's again.
    void join();

private:
    void run();
    void execute(const MechanicsCommand& c);
    // Reads the axis at the grid times before t (or also at t) while it is not at rest.
    void periodic_until(TimePs t_ps, bool inclusive);
    void read(TimePs t_ps, bool periodic);
    void publish(bool ended);

    int m_axis;
    StepperMotor& m_motor;
    const CarriageDrive& m_drive;
    TimePs m_period_ps;

    // Shared, under m_mutex.
    std::mutex m_mutex;
    std::condition_variable m_cv_work;
    std::condition_variable m_cv_published;
    std::vector<MechanicsCommand> m_queue;
    std::vector<AxisReading> m_published;
    std::int64_t m_syncs_published = 0;
    bool m_ended = false;
    std::exception_ptr m_error;
    // The thread's side.
    std::vector<AxisReading> m_readings;
    std::int64_t m_syncs = 0;
    TimePs m_next_grid_ps;  // the first grid time not yet considered

    std::thread m_thread;
};

}  // namespace cnc::mech
