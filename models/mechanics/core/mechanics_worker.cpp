#include "mechanics/core/mechanics_worker.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace cnc::mech {

namespace {

// Commands handed to the workers at a time: their locks are taken once per batch, and each worker, woken once per
// batch, stays a few hundred microseconds of its work behind the simulation.
constexpr std::size_t kBatchCommands = 1024;

}  // namespace

double MechanicsWorker::Replay::carriage_mm(TimePs t_ps) const {
    if (m_next < readings.size()) {
        const AxisReading& r = readings[m_next];
        if (r.t_ps < t_ps || (r.t_ps == t_ps && r.periodic && !m_periodic))
            throw std::logic_error("mechanics worker: an axis was read at " + std::to_string(r.t_ps) +
                                   " ps, where the sampler took no sample");
        if (r.t_ps == t_ps && r.periodic == m_periodic) {
            ++m_next;
            m_at_rest = r.at_rest;
            m_mm = r.carriage_mm;
            return m_mm;
        }
    }
    // Only a periodic sample may find the axis unread, and only where it rests.
    if (!m_periodic || !m_at_rest)
        throw std::logic_error("mechanics worker: an axis was not read at " + std::to_string(t_ps) + " ps");
    return m_mm;
}

void MechanicsWorker::Replay::drop_used() {
    readings.erase(readings.begin(), readings.begin() + static_cast<std::ptrdiff_t>(m_next));
    m_next = 0;
}

MechanicsWorker::MechanicsWorker(Axis x, Axis y, geom::Vec2 origin_mm, TimePs period_ps)
    : m_sampler(m_replay[0], m_replay[1], origin_mm, period_ps) {
    const Axis axes[2] = {x, y};
    for (int a = 0; a < 2; ++a)
        m_workers[a] = std::make_unique<AxisWorker>(a, *axes[a].motor, *axes[a].drive, period_ps);
    m_batch.reserve(kBatchCommands);
}

// Without finish(), each worker is told to end and joined by its own destructor.
MechanicsWorker::~MechanicsWorker() = default;

void MechanicsWorker::microstep(int axis, TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) {
    push({Kind::Microstep, static_cast<std::int8_t>(axis), false, microsteps_per_full_step, t_ps, microstep_index});
}

void MechanicsWorker::enable(int axis, TimePs t_ps, bool enabled) {
    push({Kind::Enable, static_cast<std::int8_t>(axis), enabled, 0, t_ps, 0});
}

void MechanicsWorker::start(TimePs t_ps) {
    push({Kind::Start, 0, false, 0, t_ps, 0});
}

void MechanicsWorker::step(TimePs t_ps) {
    push({Kind::Step, 0, false, 0, t_ps, 0});
}

void MechanicsWorker::enable_changed(TimePs t_ps) {
    push({Kind::EnableChanged, 0, false, 0, t_ps, 0});
}

void MechanicsWorker::mark(TimePs t_ps) {
    if (m_finished || t_ps <= m_marked_ps) return;
    m_marked_ps = t_ps;
    push({Kind::Sync, 0, false, 0, t_ps, 0});
    flush();
}

TimePs MechanicsWorker::ready_ps(TimePs t_ps) {
    mark(t_ps);
    std::int64_t ready = m_workers[0]->syncs_published();
    ready = std::min(ready, m_workers[1]->syncs_published());
    TimePs ready_ps = m_merged_ps;
    std::int64_t marks = m_marks_merged;
    for (const Command& c : m_to_merge) {
        if (marks >= ready) break;
        if (c.kind != Kind::Sync) continue;
        ++marks;
        ready_ps = c.t_ps;
    }
    return ready_ps;
}

std::vector<ToolSample> MechanicsWorker::take_before(TimePs t_ps) {
    mark(t_ps);
    if (!m_finished) merge_until(t_ps);
    return m_sampler.take_before(t_ps);
}

MechanicsWorker::End MechanicsWorker::finish(TimePs bound_ps, bool bound_inclusive) {
    push({Kind::End, 0, bound_inclusive, 0, bound_ps, 0});
    flush();
    m_finished = true;
    for (int a = 0; a < 2; ++a) {
        m_workers[a]->join();
        m_workers[a]->take_readings(std::numeric_limits<std::int64_t>::max(), m_replay[a].readings);
    }
    for (const Command& c : m_to_merge) merge(c);
    m_to_merge.clear();
    return m_end;
}

void MechanicsWorker::push(const Command& c) {
    m_batch.push_back(c);
    if (c.kind != Kind::Microstep && c.kind != Kind::Enable) m_to_merge.push_back(c);
    if (m_batch.size() < kBatchCommands) return;
    // The calls come in time order: those before this one's time have all been made.
    mark(c.t_ps);
    flush();
}

void MechanicsWorker::flush() {
    if (m_batch.empty()) return;
    for (const std::unique_ptr<AxisWorker>& w : m_workers) w->push(m_batch);
    m_batch.clear();
}

void MechanicsWorker::merge_until(TimePs t_ps) {
    std::int64_t marks = m_marks_merged;
    std::size_t n = 0;
    while (n < m_to_merge.size()) {
        const Command& c = m_to_merge[n++];
        if (c.kind != Kind::Sync) continue;
        ++marks;
        if (c.t_ps >= t_ps) break;
    }
    if (marks == m_marks_merged) return;  // merged there already
    // Up to the last mark found: what follows it may not have been read yet.
    while (m_to_merge[n - 1].kind != Kind::Sync) --n;
    for (int a = 0; a < 2; ++a) m_workers[a]->take_readings(marks, m_replay[a].readings);
    for (std::size_t k = 0; k < n; ++k) merge(m_to_merge[k]);
    m_merged_ps = m_to_merge[n - 1].t_ps;
    m_to_merge.erase(m_to_merge.begin(), m_to_merge.begin() + static_cast<std::ptrdiff_t>(n));
    m_marks_merged = marks;
    for (Replay& r : m_replay) r.drop_used();
}

void MechanicsWorker::merge(const Command& c) {
    std::optional<TimePs> next;
    switch (c.kind) {
        case Kind::Start:
        case Kind::Step:
            periodic_until(c.t_ps, true);
            for (Replay& r : m_replay) r.expect(false);
            next = c.kind == Kind::Start ? m_sampler.on_start(c.t_ps) : m_sampler.on_step(c.t_ps);
            break;
        case Kind::EnableChanged:
            periodic_until(c.t_ps, true);
            next = m_sampler.on_enable(c.t_ps);
            break;
        case Kind::Sync:
            periodic_until(c.t_ps, false);
            break;
        case Kind::End:
            periodic_until(c.t_ps, c.flag);
            m_end.periodic_past_bound = m_next_periodic_ps.has_value();
            break;
        case Kind::Microstep:
        case Kind::Enable:
            break;
    }
    if (next) m_next_periodic_ps = next;
}

void MechanicsWorker::periodic_until(TimePs t_ps, bool inclusive) {
    while (m_next_periodic_ps && (*m_next_periodic_ps < t_ps || (inclusive && *m_next_periodic_ps == t_ps))) {
        const TimePs due_ps = *m_next_periodic_ps;
        for (Replay& r : m_replay) r.expect(true);
        m_next_periodic_ps = m_sampler.on_period(due_ps);
        m_end.last_periodic_ps = due_ps;
    }
}

}  // namespace cnc::mech
