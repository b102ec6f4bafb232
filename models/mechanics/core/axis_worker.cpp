#include "mechanics/core/axis_worker.hpp"

namespace cnc::mech {

AxisWorker::AxisWorker(int axis, StepperMotor& motor, const CarriageDrive& drive, TimePs period_ps)
    : m_axis(axis), m_motor(motor), m_drive(drive), m_period_ps(period_ps), m_next_grid_ps(period_ps) {
    m_thread = std::thread([this] { run(); });
}

AxisWorker::~AxisWorker() {
    if (!m_thread.joinable()) return;
    push({{MechanicsCommand::Kind::End, 0, false, 0, 0, 0}});
    m_thread.join();
}

void AxisWorker::push(const std::vector<MechanicsCommand>& commands) {
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_queue.insert(m_queue.end(), commands.begin(), commands.end());
    }
    m_cv_work.notify_one();
}

std::int64_t AxisWorker::syncs_published() {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_syncs_published;
}

void AxisWorker::take_readings(std::int64_t syncs, std::vector<AxisReading>& to) {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_cv_published.wait(lock, [&] { return m_syncs_published >= syncs || m_ended || m_error; });
    if (m_error) std::rethrow_exception(m_error);
    to.insert(to.end(), m_published.begin(), m_published.end());
    m_published.clear();
}

void AxisWorker::join() {
    if (m_thread.joinable()) m_thread.join();
    if (m_error) std::rethrow_exception(m_error);
}

void AxisWorker::run() {
    std::vector<MechanicsCommand> work;
    try {
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(m_mutex);
                m_cv_work.wait(lock, [&] { return !m_queue.empty(); });
                work.swap(m_queue);
            }
            for (const MechanicsCommand& c : work) {
                if (c.kind == MechanicsCommand::Kind::End) {
                    periodic_until(c.t_ps, c.flag);
                    publish(true);
                    return;
                }
                execute(c);
            }
            work.clear();
        }
    } catch (...) {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_error = std::current_exception();
        m_cv_published.notify_all();
    }
}

void AxisWorker::execute(const MechanicsCommand& c) {
    using Kind = MechanicsCommand::Kind;
    switch (c.kind) {
        case Kind::Microstep:
        case Kind::Enable:
            if (c.axis != m_axis) return;  // the other axis's: nothing here moves until this axis is asked
            periodic_until(c.t_ps, true);
            if (c.kind == Kind::Microstep)
                m_motor.on_microstep(c.t_ps, c.index, c.microsteps);
            else
                m_motor.on_enable(c.t_ps, c.flag);
            return;
        case Kind::Start:
        case Kind::Step:
            periodic_until(c.t_ps, true);
            read(c.t_ps, false);
            return;
        case Kind::EnableChanged:
            return;
        case Kind::Sync:
            periodic_until(c.t_ps, false);
            ++m_syncs;
            publish(false);
            return;
        case Kind::End:
            break;
    }
}

void AxisWorker::periodic_until(TimePs t_ps, bool inclusive) {
    if (m_period_ps <= 0) return;
    auto due = [&] { return m_next_grid_ps < t_ps || (inclusive && m_next_grid_ps == t_ps); };
    while (due() && !m_drive.at_rest()) {
        read(m_next_grid_ps, true);
        m_next_grid_ps += m_period_ps;
    }
    // At rest until a call of this axis moves it: the grid times up to t pass unread.
    if (due()) m_next_grid_ps = first_edge_after(inclusive ? t_ps : t_ps - 1, m_period_ps) * m_period_ps;
}

void AxisWorker::read(TimePs t_ps, bool periodic) {
    const double mm = m_drive.carriage_mm(t_ps);
    m_readings.push_back({t_ps, periodic, m_drive.at_rest(), mm});
}

void AxisWorker::publish(bool ended) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_published.insert(m_published.end(), m_readings.begin(), m_readings.end());
    m_readings.clear();
    m_syncs_published = m_syncs;
    m_ended = ended;
    m_cv_published.notify_all();
}

}  // namespace cnc::mech
