#include "avr/loop_skipper.hpp"

#include <algorithm>
#include <cstring>

#include <sim_avr.h>
#include <sim_io.h>

namespace cnc::avr {

struct LoopSkipper::Io {
    avr_io_read_t read = nullptr;
    void* read_param = nullptr;
    bool pure_read = false;
    avr_io_write_t write = nullptr;
    void* write_param = nullptr;
    LoopSkipper* self = nullptr;

    static std::uint8_t watch_read(avr_t* avr, avr_io_addr_t addr, void* param) {
        auto* io = static_cast<Io*>(param);
        if (!io->pure_read) io->self->disturb();
        return io->read(avr, addr, io->read_param);
    }
    static void watch_write(avr_t* avr, avr_io_addr_t addr, std::uint8_t v, void* param) {
        auto* io = static_cast<Io*>(param);
        io->self->disturb();
        io->write(avr, addr, v, io->write_param);
    }
};

LoopSkipper::LoopSkipper(avr_t* avr, const std::vector<std::uint16_t>& pure_reads)
    : m_avr(avr), m_io(MAX_IOs), m_snapshot(static_cast<std::size_t>(avr->ramend) + 1) {
    for (std::size_t i = 0; i < m_io.size(); ++i) {
        auto& slot = avr->io[i];
        Io& io = m_io[i];
        io.self = this;
        const auto addr = static_cast<std::uint16_t>(AVR_IO_TO_DATA(i));
        io.pure_read = std::find(pure_reads.begin(), pure_reads.end(), addr) != pure_reads.end();
        if (slot.r.c != nullptr) {
            io.read = slot.r.c;
            io.read_param = slot.r.param;
            slot.r.c = Io::watch_read;
            slot.r.param = &io;
        }
        if (slot.w.c != nullptr) {
            io.write = slot.w.c;
            io.write_param = slot.w.param;
            slot.w.c = Io::watch_write;
            slot.w.param = &io;
        }
    }
}

LoopSkipper::~LoopSkipper() = default;

LoopSkipper::CpuState LoopSkipper::cpu_state() const {
    CpuState s{};
    std::memcpy(s.data(), m_avr->data, 32);
    std::memcpy(s.data() + 32, m_avr->sreg, 8);  // simavr keeps SREG in sreg[], not in the data space
    s[40] = static_cast<std::uint8_t>(m_avr->interrupt_state);
    return s;
}

std::uint16_t LoopSkipper::sp() const {
    return static_cast<std::uint16_t>(m_avr->data[R_SPL] | (m_avr->data[R_SPH] << 8));
}

void LoopSkipper::after_step(std::uint32_t pc_before) {
    const std::uint32_t pc = m_avr->pc;
    if (pc > pc_before || m_avr->state != cpu_Running) return;  // not the end of an iteration (a jump to itself is)
    Visit& v = m_visits[(pc >> 1) & (m_visits.size() - 1)];
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const CpuState cpu = cpu_state();
    const std::uint16_t stack = sp();
    const bool repeated = v.pc == pc && v.epoch == m_epoch && v.sp == stack && v.cpu == cpu;
    if (repeated) {
        const Cycle period = now - v.cycle;
        const std::size_t n = m_snapshot.size();
        if (m_armed_pc == pc && m_armed_epoch == m_epoch && m_armed_period == period &&
            std::memcmp(m_snapshot.data(), m_avr->data, n) == 0) {
            skip(period);
        } else {
            std::memcpy(m_snapshot.data(), m_avr->data, n);
            m_armed_pc = pc;
            m_armed_period = period;
            m_armed_epoch = m_epoch;
        }
    }
    v = Visit{pc, static_cast<Cycle>(m_avr->cycle), m_epoch, stack, cpu};
}

void LoopSkipper::skip(Cycle period) {
    // The first cycle timer due (simavr's list is sorted) is the first event; the run_until boundary is one of them.
    const avr_cycle_timer_slot_t* next = m_avr->cycle_timers.timer;
    if (next == nullptr || period <= 0) return;
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const Cycle event = static_cast<Cycle>(next->when);
    // A timer due at `event` is processed after the first instruction that ends at or past it: iterations ending
    // before it see nothing of it.
    if (event <= now) return;
    const Cycle iterations = (event - 1 - now) / period;
    if (iterations <= 0) return;
    m_avr->cycle += static_cast<avr_cycle_count_t>(iterations * period);
    ++m_stats.skips;
    m_stats.skipped_cycles += static_cast<std::uint64_t>(iterations * period);
}

}  // namespace cnc::avr
