#include "mechanics/carriage.hpp"
#include "common/sc_time.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

namespace {

void require_complete(const CarriageAxis& a, const char* axis, bool worker_thread) {
    if (a.step_event == nullptr || a.drive == nullptr || (worker_thread && a.motor == nullptr))
        throw BadInput("", std::string("carriage axis ") + axis + " needs a step event and a drive" +
                               (worker_thread ? " and a motor" : ""));
}

const CarriageConfig& checked(const CarriageConfig& cfg) {
    require_complete(cfg.x, "x", cfg.worker_thread);
    require_complete(cfg.y, "y", cfg.worker_thread);
    return cfg;
}

void write_position(PositionSignal& signal, double mm) {
    if (std::abs(mm - signal.read()) > kPositionSignalResolutionMm) signal.write(mm);
}

// The sampling period in the kernel's picoseconds, as sc_time rounds it.
TimePs period_ps(double sample_hz) {
    if (sample_hz <= 0.0) return 0;
    return static_cast<TimePs>(sc_core::sc_time(1.0 / sample_hz, sc_core::SC_SEC).value());
}

}  // namespace

Carriage::Carriage(const sc_core::sc_module_name& name, const CarriageConfig& cfg)
    : sc_core::sc_module(name),
      m_cfg(checked(cfg)),
      m_sampler(*cfg.x.drive, *cfg.y.drive, cfg.origin, period_ps(cfg.sample_hz)),
      m_carriage_x_mm("carriage_x_mm", cfg.worker_thread ? 0.0 : position().x_mm),
      m_carriage_y_mm("carriage_y_mm", cfg.worker_thread ? 0.0 : position().y_mm) {
    if (cfg.worker_thread) {
        m_worker = std::make_unique<MechanicsWorker>(MechanicsWorker::Axis{cfg.x.motor, cfg.x.drive},
                                                     MechanicsWorker::Axis{cfg.y.motor, cfg.y.drive}, cfg.origin,
                                                     period_ps(cfg.sample_hz));
    }
    SC_HAS_PROCESS(Carriage);
    SC_METHOD(on_step);
    sensitive << *cfg.x.step_event << *cfg.y.step_event;
    dont_initialize();
    SC_METHOD(on_enable);
    for (const CarriageAxis* a : {&cfg.x, &cfg.y}) {
        if (a->enable_event != nullptr) sensitive << *a->enable_event;
    }
    dont_initialize();
    SC_METHOD(on_period);
    sensitive << m_period_ev;
    dont_initialize();
}

void Carriage::start_of_simulation() {
    on_event(&MechanicsWorker::start, &ToolSampler::on_start);
}

void Carriage::on_step() {
    on_event(&MechanicsWorker::step, &ToolSampler::on_step);
}

void Carriage::on_enable() {
    on_event(&MechanicsWorker::enable_changed, &ToolSampler::on_enable);
}

void Carriage::on_event(void (MechanicsWorker::*to_worker)(TimePs),
                        std::optional<TimePs> (ToolSampler::*to_sampler)(TimePs)) {
    const TimePs t = now_ps();
    if (m_worker) {
        ((*m_worker).*to_worker)(t);
        return;
    }
    if (const std::optional<TimePs> next = (m_sampler.*to_sampler)(t)) m_period_ev.notify(ps_time(*next - t));
    write_positions();
}

// Stops once both axes are at rest, so that a finished job leaves the kernel without events.
void Carriage::on_period() {
    const TimePs t = now_ps();
    if (const std::optional<TimePs> next = m_sampler.on_period(t)) m_period_ev.notify(ps_time(*next - t));
    write_positions();
}

void Carriage::write_positions() {
    const geom::Vec2& pos = m_sampler.samples().back().pos;
    write_position(m_carriage_x_mm, pos.x_mm);
    write_position(m_carriage_y_mm, pos.y_mm);
}

geom::Vec2 Carriage::position() const {
    if (m_cfg.worker_thread) throw std::logic_error("the carriage's position is the worker's while it runs");
    const TimePs t = now_ps();
    return m_cfg.origin + geom::Vec2{m_cfg.x.drive->carriage_mm(t), m_cfg.y.drive->carriage_mm(t)};
}

const std::vector<ToolSample>& Carriage::samples() const {
    return m_worker ? m_worker->samples_left() : m_sampler.samples();
}

std::vector<ToolSample> Carriage::take_samples_before(TimePs t_ps) {
    if (!m_worker) return m_sampler.take_before(t_ps);
    // Every call up to now has been made: the worker may take the samples before now while the simulation runs on.
    m_worker->mark(now_ps());
    return m_worker->take_before(t_ps);
}

TimePs Carriage::samples_ready_ps() {
    return m_worker ? m_worker->ready_ps(now_ps()) : now_ps();
}

std::optional<MechanicsWorker::End> Carriage::finish(TimePs bound_ps, bool bound_inclusive) {
    if (!m_worker) return std::nullopt;
    return m_worker->finish(bound_ps, bound_inclusive);
}

double WorkerMotor::shaft_angle_deg(TimePs) const {
    throw std::logic_error("a motor on the mechanics worker is not read while it runs");
}

}  // namespace cnc::mech
