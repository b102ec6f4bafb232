#include "mechanics/core/mechanics_worker.hpp"

#include <iterator>
#include <limits>
#include <utility>

namespace cnc::mech {

namespace {

// Commands handed to the worker at a time: the lock is taken once per batch, and the worker, woken once per
// batch, stays a few hundred microseconds of its work behind the simulation.
constexpr std::size_t kBatchCommands = 1024;

}  // namespace

MechanicsWorker::MechanicsWorker(StepperMotor& x, StepperMotor& y, ToolSampler& sampler)
    : m_motors{&x, &y}, m_sampler(sampler) {
    m_batch.reserve(kBatchCommands);
    m_thread = std::thread([this] { run(); });
}

MechanicsWorker::~MechanicsWorker() {
    if (!m_thread.joinable()) return;
    push({Kind::End, 0, false, 0, 0, 0});
    flush();
    m_thread.join();
}

void MechanicsWorker::microstep(int axis, TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) {
    push({Kind::Microstep, static_cast<std::int8_t>(axis), false, microsteps_per_full_step, t_ps, microstep_index});
}

void MechanicsWorker::enable(int axis, TimePs t_ps, bool enabled) {
    push({Kind::Enable, static_cast<std::int8_t>(axis), enabled, 0, t_ps, 0});
}

void MechanicsWorker::start(TimePs t_ps) { push({Kind::Start, 0, false, 0, t_ps, 0}); }

void MechanicsWorker::step(TimePs t_ps) { push({Kind::Step, 0, false, 0, t_ps, 0}); }

void MechanicsWorker::mark(TimePs t_ps) {
    if (m_finished || t_ps <= m_marked_ps) return;
    m_marked_ps = t_ps;
    push({Kind::Sync, 0, false, 0, t_ps, 0});
    flush();
}

std::vector<ToolSample> MechanicsWorker::take_before(TimePs t_ps) {
    mark(t_ps);
    std::unique_lock<std::mutex> lock(m_mutex);
    if (!m_finished) {
        m_cv_synced.wait(lock, [&] { return m_synced_ps >= t_ps || m_error; });
        if (m_error) std::rethrow_exception(m_error);
    }
    return take_samples_before(m_ready, t_ps);
}

MechanicsWorker::End MechanicsWorker::finish(TimePs bound_ps, bool bound_inclusive) {
    push({Kind::End, 0, bound_inclusive, 0, bound_ps, 0});
    flush();
    m_thread.join();
    m_finished = true;
    if (m_error) std::rethrow_exception(m_error);
    return m_end;
}

void MechanicsWorker::push(const Command& c) {
    m_batch.push_back(c);
    if (m_batch.size() >= kBatchCommands) flush();
}

void MechanicsWorker::flush() {
    if (m_batch.empty()) return;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_queue.insert(m_queue.end(), m_batch.begin(), m_batch.end());
    }
    m_batch.clear();
    m_cv_work.notify_one();
}

void MechanicsWorker::run() {
    std::vector<Command> work;
    try {
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(m_mutex);
                m_cv_work.wait(lock, [&] { return !m_queue.empty(); });
                work.swap(m_queue);
            }
            for (const Command& c : work) {
                if (c.kind == Kind::End) {
                    periodic_until(c.t_ps, c.flag);
                    m_end.periodic_past_bound = m_next_periodic_ps.has_value();
                    publish(std::numeric_limits<TimePs>::max());
                    return;
                }
                execute(c);
            }
            work.clear();
        }
    } catch (...) {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_error = std::current_exception();
        m_cv_synced.notify_all();
    }
}

void MechanicsWorker::execute(const Command& c) {
    switch (c.kind) {
    case Kind::Microstep:
        periodic_until(c.t_ps, true);
        m_motors[c.axis]->on_microstep(c.t_ps, c.index, c.microsteps);
        return;
    case Kind::Enable:
        periodic_until(c.t_ps, true);
        m_motors[c.axis]->on_enable(c.t_ps, c.flag);
        return;
    case Kind::Start:
        m_sampler.on_start(c.t_ps);
        return;
    case Kind::Step:
        periodic_until(c.t_ps, true);
        if (const std::optional<TimePs> next = m_sampler.on_step(c.t_ps)) m_next_periodic_ps = next;
        return;
    case Kind::Sync:
        periodic_until(c.t_ps, false);
        publish(c.t_ps);
        return;
    case Kind::End:
        break;
    }
}

void MechanicsWorker::periodic_until(TimePs t_ps, bool inclusive) {
    while (m_next_periodic_ps && (*m_next_periodic_ps < t_ps || (inclusive && *m_next_periodic_ps == t_ps))) {
        const TimePs due_ps = *m_next_periodic_ps;
        m_next_periodic_ps = m_sampler.on_period(due_ps);
        m_end.last_periodic_ps = due_ps;
    }
}

void MechanicsWorker::publish(TimePs before_ps) {
    std::vector<ToolSample> final_samples = m_sampler.take_before(before_ps);
    std::lock_guard<std::mutex> lock(m_mutex);
    m_ready.insert(m_ready.end(), std::make_move_iterator(final_samples.begin()),
                   std::make_move_iterator(final_samples.end()));
    m_synced_ps = before_ps;
    m_cv_synced.notify_all();
}

}  // namespace cnc::mech
