#include "avr/loop_skipper.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include <sim_avr.h>
#include <sim_io.h>

#include "avr/core/data_access.hpp"

namespace cnc::avr {

struct LoopSkipper::Io {
    avr_io_read_t read = nullptr;
    void* read_param = nullptr;
    bool pure_read = false;
    bool pin_read = false;  // a PINx
    avr_io_write_t write = nullptr;
    void* write_param = nullptr;
    LoopSkipper* self = nullptr;

    static std::uint8_t watch_read(avr_t* avr, avr_io_addr_t addr, void* param) {
        auto* io = static_cast<Io*>(param);
        if (io->pin_read) io->self->m_pins_read = true;
        if (!io->pure_read) io->self->disturb();
        return io->read(avr, addr, io->read_param);
    }
    static void watch_write(avr_t* avr, avr_io_addr_t addr, std::uint8_t v, void* param) {
        auto* io = static_cast<Io*>(param);
        io->self->disturb();
        io->write(avr, addr, v, io->write_param);
    }
};

LoopSkipper::LoopSkipper(avr_t* avr, const std::vector<std::uint16_t>& pins,
                         const std::vector<std::uint16_t>& pure_reads, std::function<Cycle()> quiet_until)
    : m_avr(avr),
      m_quiet_until(std::move(quiet_until)),
      m_io(MAX_IOs),
      m_snapshot(static_cast<std::size_t>(avr->ramend) + 1),
      m_touched(m_snapshot.size()),
      m_written(m_snapshot.size()) {
    for (std::size_t i = 0; i < m_io.size(); ++i) {
        auto& slot = avr->io[i];
        Io& io = m_io[i];
        io.self = this;
        const auto addr = static_cast<std::uint16_t>(AVR_IO_TO_DATA(i));
        io.pin_read = std::find(pins.begin(), pins.end(), addr) != pins.end();
        io.pure_read = io.pin_read || std::find(pure_reads.begin(), pure_reads.end(), addr) != pure_reads.end();
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

void LoopSkipper::backward_jump() {
    const std::uint32_t pc = m_avr->pc;
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const CpuState cpu = cpu_state();
    const std::uint16_t stack = sp();
    if (pc == m_loop.pc) {
        if (m_loop.epoch == m_epoch && m_loop.sp == stack && m_loop.cpu == cpu &&
            std::memcmp(m_snapshot.data(), m_avr->data, m_snapshot.size()) == 0) {
            if (m_recording && m_footprint_known) keep_proof(now - m_loop.cycle);
            m_recording = false;  // the snapshot stands: the next iterations prove nothing new
            skip(now - m_loop.cycle);
        } else {
            if (reuse_proof(pc, stack, cpu)) return;
            std::memcpy(m_snapshot.data(), m_avr->data, m_snapshot.size());
            start_recording();
        }
        m_loop = Visit{pc, static_cast<Cycle>(m_avr->cycle), m_epoch, stack, cpu};
        return;
    }
    if (reuse_proof(pc, stack, cpu)) return;
    // Any backward-jump target whose last two visits look alike becomes the watched one, unless the watched one was
    // visited during that iteration: then both are in the same loop (an inner loop, a called function), and the one
    // watched already keeps its snapshot.
    Visit& v = m_visits[(pc >> 1) & (m_visits.size() - 1)];
    if (v.pc == pc && v.epoch == m_epoch && v.sp == stack && v.cpu == cpu && m_loop.cycle < v.cycle) {
        std::memcpy(m_snapshot.data(), m_avr->data, m_snapshot.size());
        m_loop = Visit{pc, now, m_epoch, stack, cpu};
        start_recording();
    }
    v = Visit{pc, now, m_epoch, stack, cpu};
}

void LoopSkipper::start_recording() {
    m_recording = true;
    m_footprint_known = true;
    ++m_stamp;
    m_reads.clear();
    m_writes.clear();
}

void LoopSkipper::before_instruction() {
    const std::uint32_t pc = m_avr->pc;
    if (pc + 3 >= m_avr->flashend) {
        m_footprint_known = false;
        return;
    }
    const std::uint8_t* flash = m_avr->flash;
    const auto word = [flash](std::uint32_t a) { return static_cast<std::uint16_t>(flash[a] | (flash[a + 1] << 8)); };
    const DataAccesses accesses = data_accesses(word(pc), word(pc + 2), m_avr->data);
    if (accesses.unmodelled) m_footprint_known = false;
    for (int i = 0; i < accesses.count; ++i) {
        const DataAccess& a = accesses.at[static_cast<std::size_t>(i)];
        if (a.addr >= m_touched.size()) {
            m_footprint_known = false;
            continue;
        }
        const bool io = a.addr >= 32 && a.addr < 32 + MAX_IOs;
        // A register with a read handler answers from outside the data space (PINx, UCSR0A).
        if (a.read && io && m_io[AVR_DATA_TO_IO(a.addr)].read != nullptr) m_footprint_known = false;
        if (m_touched[a.addr] != m_stamp) {
            m_touched[a.addr] = m_stamp;
            if (a.read) m_reads.push_back(a.addr);
        }
        if (a.write && m_written[a.addr] != m_stamp) {
            m_written[a.addr] = m_stamp;
            m_writes.push_back(a.addr);
        }
    }
}

void LoopSkipper::keep_proof(Cycle period) {
    Proof& p = m_proofs[m_next_proof];
    m_next_proof = (m_next_proof + 1) % m_proofs.size();
    p.at = m_loop;
    p.period = period;
    p.reads.clear();
    p.writes.clear();
    for (const std::uint16_t a : m_reads) p.reads.emplace_back(a, m_snapshot[a]);
    for (const std::uint16_t a : m_writes) p.writes.emplace_back(a, m_avr->data[a]);
}

bool LoopSkipper::reuse_proof(std::uint32_t pc, std::uint16_t stack, const CpuState& cpu) {
    for (const Proof& p : m_proofs) {
        if (p.period == 0 || p.at.pc != pc || p.at.sp != stack || p.at.cpu != cpu) continue;
        const bool same = std::all_of(p.reads.begin(), p.reads.end(),
                                      [this](const auto& r) { return m_avr->data[r.first] == r.second; });
        if (!same) continue;
        if (skip(p.period) == 0) return false;
        for (const auto& [a, v] : p.writes) m_avr->data[a] = v;
        ++m_stats.reused;
        disturb();  // the watched loop's snapshot is of another state
        return true;
    }
    return false;
}

Cycle LoopSkipper::skip(Cycle period) {
    if (period <= 0) return 0;
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const Cycle event = m_quiet_until();
    // An event at `event` is seen after the first instruction that ends at or past it: iterations ending before it
    // see nothing of it.
    if (event <= now) return 0;
    const Cycle iterations = (event - 1 - now) / period;
    if (iterations <= 0) return 0;
    m_avr->cycle += static_cast<avr_cycle_count_t>(iterations * period);
    ++m_stats.skips;
    m_stats.skipped_cycles += static_cast<std::uint64_t>(iterations * period);
    return iterations;
}

}  // namespace cnc::avr
