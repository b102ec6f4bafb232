#include "avr/avr_core.hpp"
#include "common/sc_time.hpp"

#include <algorithm>
#include <cmath>

#include "uart/core/line_receiver.hpp"

namespace cnc::avr {

namespace {

// Cycles the AVR keeps away from a frame decision it has not been told about: a run stops past its limit by at most
// 7 cycles (an instruction of up to 4 cycles, CALL or RET, ending past it, then an interrupt's 4-cycle response; or a
// wake-up from sleep, vector 8 cycles after a flag raised before the limit).
constexpr Cycle kDecisionMarginCycles = 8;

}  // namespace

AvrCore::AvrCore(const sc_core::sc_module_name& name, const AvrCoreConfig& cfg)
    : sc_module(name),
      step_x("step_x"),
      dir_x("dir_x"),
      en_x("en_x"),
      step_y("step_y"),
      dir_y("dir_y"),
      en_y("en_y"),
      head("head"),
      txd("txd"),
      rxd("rxd"),
      m_cfg(cfg),
      m_chip(std::make_unique<AvrChip>(cfg)),
      m_lines{&step_x, &dir_x, &en_x, &step_y, &dir_y, &en_y, &head, &txd} {
    SC_HAS_PROCESS(AvrCore);
    for (int i = 0; i < kLineCount; ++i) m_lines[static_cast<std::size_t>(i)]->initialize(m_chip->initial_level(i));
    SC_THREAD(run);
    SC_METHOD(on_rxd);  // also runs at initialisation, to read the idle level
    sensitive << rxd;
}

AvrCoreStats AvrCore::stats() const {
    AvrCoreStats s;
    s.cycles = m_chip->cycle();
    s.usart = m_chip->usart().stats();
    s.rx_false_starts = m_rx_false_starts;
    s.rx_late_decisions = m_rx_late;
    return s;
}

Cycle AvrCore::first_cycle_at_or_after(TimePs t_ps) const {
    return std::max<Cycle>(0, m_chip->clock().first_at_or_after(t_ps));
}

void AvrCore::wait_until_ps(TimePs t_ps) {
    const TimePs now = now_ps();
    if (t_ps > now) wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t_ps - now)));
}

Cycle AvrCore::run_ahead_limit() const {
    // A start bit seen during the next replay must still have its decision ahead of the AVR.
    const uart::BitClock clk = m_chip->rx_clock();
    const uart::FrameFormat fmt = m_chip->rx_format();
    const Cycle decision_cycles = (2 * (fmt.bits_per_frame() - 1) + 1) * clk.ticks_per_bit / 2;
    const Cycle q = std::min<Cycle>(m_cfg.quantum_cycles, decision_cycles - kDecisionMarginCycles);
    Cycle limit = m_chip->cycle() + std::max<Cycle>(1, q);
    if (m_rx) limit = std::min(limit, m_rx->decision_cycle);
    return limit;
}

Cycle AvrCore::replay_bound(Cycle c) const {
    // The core's cycle count jumps past timer events now and then (the interrupt response's 4 cycles, a wake-up from
    // sleep): those are processed at the next step, and their edges recorded then. Replaying past them would write
    // those edges late, so the replay stops just before the first event still due.
    const auto due = m_chip->next_event();
    return due && *due <= c ? *due - 1 : c;
}

void AvrCore::replay(Cycle upto) {
    for (const LineEvent& e : m_chip->take_events(upto)) {
        wait_until_ps(cycle_ps(e.cycle));
        m_lines[static_cast<std::size_t>(e.line)]->write(e.level);
    }
}

void AvrCore::run() {
    for (;;) {
        if (m_chip->state() != ChipState::Running && !m_rx && !m_chip->next_event()) {
            // Nothing can happen any more but a frame on RXD (counted as lost or stored): sleep until one comes.
            wait(rxd.value_changed_event());
            m_chip->run_until(first_cycle_at_or_after(now_ps()));
        }
        const Cycle limit = run_ahead_limit();
        if (limit > m_chip->cycle()) m_chip->run_until(limit);
        if (m_rx && m_chip->cycle() >= m_rx->decision_cycle) {
            const Cycle decision = replay_bound(m_rx->decision_cycle);
            replay(decision);
            wait_until_ps(cycle_ps(decision));
            // Let a writer of rxd at this very instant (delta 0) reach on_rxd (delta 1) before decoding.
            wait(sc_core::SC_ZERO_TIME);
            wait(sc_core::SC_ZERO_TIME);
            decide_frame();
        }
        const Cycle end = replay_bound(m_chip->cycle());
        replay(end);
        wait_until_ps(cycle_ps(end));
        if (!m_stop_notified && m_chip->state() != ChipState::Running) {
            m_stop_notified = true;
            m_stopped_ev.notify(sc_core::SC_ZERO_TIME);
        }
    }
}

void AvrCore::on_rxd() {
    const bool level = rxd.read();
    if (!m_rx_started) {  // initialisation: the line's idle level
        m_rx_started = true;
        m_rx_level = level;
        m_rx_line.initial = level;
        return;
    }
    if (level == m_rx_level) return;
    m_rx_level = level;
    m_rx_line.add(now_ps(), level);
    if (!level && !m_rx) start_frame(now_ps());  // a high-to-low transition on an idle receiver
}

void AvrCore::start_frame(TimePs t_fall_ps) {
    auto f = std::make_unique<PendingFrame>();
    f->t_fall_ps = t_fall_ps;
    f->clk = m_chip->rx_clock();
    f->fmt = m_chip->rx_format();
    f->t_decision_ps = t_fall_ps + uart::decision_offset_ps(f->clk, f->fmt);
    f->start_cycle = first_cycle_at_or_after(t_fall_ps);
    f->decision_cycle = first_cycle_at_or_after(f->t_decision_ps);
    if (f->decision_cycle < m_chip->cycle()) ++m_rx_late;
    m_rx = std::move(f);
}

void AvrCore::decide_frame() {
    const PendingFrame f = *m_rx;
    m_rx.reset();
    const uart::RxFrame frame = uart::receive_frame(m_rx_line, f.t_fall_ps, f.clk, f.fmt);
    if (frame.status == uart::RxStatus::FalseStart) ++m_rx_false_starts;
    m_chip->deliver_rx(f.start_cycle, f.decision_cycle, frame);

    // Keep only the line history the next frame can need.
    const bool level_at_decision = m_rx_line.level_at(f.t_decision_ps);
    std::vector<Edge> later;
    for (const Edge& e : m_rx_line.edges)
        if (e.t_ps > f.t_decision_ps) later.push_back(e);
    // A start bit that began during this frame's stop bit (a sender slightly faster than the receiver) is
    // found by the idle receiver at its next sample: it starts the next frame from its own edge.
    const TimePs stop_bit_start = f.t_fall_ps + f.clk.bit_edge(f.fmt.bits_per_frame() - 1);
    TimePs fall_in_stop = -1;
    for (const Edge& e : m_rx_line.edges)
        if (!e.level && e.t_ps > stop_bit_start && e.t_ps <= f.t_decision_ps) fall_in_stop = e.t_ps;
    m_rx_line.initial = level_at_decision;
    m_rx_line.edges = later;
    if (fall_in_stop >= 0 && !level_at_decision) {
        m_rx_line.initial = true;
        m_rx_line.edges.insert(m_rx_line.edges.begin(), Edge{fall_in_stop, false});
        start_frame(fall_in_stop);
    } else if (level_at_decision && !later.empty()) {
        start_frame(later.front().t_ps);  // the line fell between the decision and now, while the receiver was busy
    }
}

}  // namespace cnc::avr
