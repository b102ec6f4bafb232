#include "avr/loop_skipper.hpp"

#include <algorithm>
#include <cstring>
#include <optional>
#include <utility>

#include <sim_avr.h>
#include <sim_interrupts.h>
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
      m_read_column(m_snapshot.size(), -1),
      m_written_column(m_snapshot.size(), -1),
      m_proof_pcs((static_cast<std::size_t>(avr->flashend) >> 1) + 1) {
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
    if (skip_delay_loop()) return;
    const std::uint32_t pc = m_avr->pc;
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const CpuState cpu = cpu_state();
    const std::uint16_t stack = sp();
    if (pc == m_loop.pc) {
        if (m_loop.epoch == m_epoch && m_loop.sp == stack && m_loop.cpu == cpu &&
            std::memcmp(m_snapshot.data(), m_avr->data, m_snapshot.size()) == 0) {
            const Cycle period = now - m_loop.cycle;
            const bool proven = m_recording && m_footprint_known;
            m_recording = false;  // the snapshot stands: the next iterations prove nothing new
            if (proven && keep_proof(period)) {
                const Proof& kept = m_proofs[(m_next_proof + m_proofs.size() - 1) % m_proofs.size()];
                if (run_on_proof(kept, 0, m_quiet_until())) return;
            } else {
                skip(period);
            }
        } else {
            if (reuse_proof(pc, stack, cpu, false)) return;
            std::memcpy(m_snapshot.data(), m_avr->data, m_snapshot.size());
            start_recording();
        }
        m_loop = Visit{pc, static_cast<Cycle>(m_avr->cycle), m_epoch, stack, cpu};
        return;
    }
    if (reuse_proof(pc, stack, cpu, false)) return;
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

// avr-libc's _delay_loop_2 (and every busy delay built on it, _delay_ms): `1: SBIW Rd, 1; BRNE 1b`, 4 cycles a turn
// and 3 for the last. Its counter changes at every turn, so no turn is idle, but k turns from a counter n >= 2 leave
// it at n - k with the flags of the last SBIW (AVR Instruction Set Manual, SBIW: N = R15, Z = 0 for R != 0,
// V = Rdh7 and not R15, C = R15 and not Rdh7, S = N xor V).
bool LoopSkipper::skip_delay_loop() {
    const std::uint32_t pc = m_avr->pc;
    if (pc + 3 >= m_avr->flashend) return false;
    const std::uint16_t sbiw = flash_word(m_avr->flash, pc);
    constexpr std::uint16_t kSbiwOne = 0x9701;   // SBIW Rd, 1: 1001 0111 KKdd KKKK, K = 1
    constexpr std::uint16_t kBrneBack = 0xF7F1;  // BRNE .-4: back to the SBIW
    if ((sbiw & 0xFFCF) != kSbiwOne || flash_word(m_avr->flash, pc + 2) != kBrneBack || !nothing_pending())
        return false;
    const int low = 24 + 2 * ((sbiw >> 4) & 3);
    const std::uint32_t n = m_avr->data[low] | (m_avr->data[low + 1] << 8);
    const std::uint32_t turns_left = n == 0 ? 0x10000 : n;  // SBIW from 0 wraps to 0xFFFF
    constexpr Cycle kTurn = 4;
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const Cycle event = m_quiet_until();
    if (event <= now) return false;
    const Cycle k = std::min<Cycle>(turns_left - 1, (event - 1 - now) / kTurn);
    if (k <= 0) return false;
    const auto before = static_cast<std::uint16_t>(turns_left - k + 1);  // the last SBIW's operand
    const auto after = static_cast<std::uint16_t>(before - 1);
    m_avr->data[low] = static_cast<std::uint8_t>(after & 0xFF);
    m_avr->data[low + 1] = static_cast<std::uint8_t>(after >> 8);
    const bool r15 = (after & 0x8000) != 0;
    const bool rdh7 = (before & 0x8000) != 0;
    m_avr->sreg[S_N] = r15;
    m_avr->sreg[S_Z] = 0;
    m_avr->sreg[S_V] = rdh7 && !r15;
    m_avr->sreg[S_C] = r15 && !rdh7;
    m_avr->sreg[S_S] = m_avr->sreg[S_N] ^ m_avr->sreg[S_V];
    m_avr->cycle += static_cast<avr_cycle_count_t>(k * kTurn);
    ++m_stats.skips;
    m_stats.skipped_cycles += static_cast<std::uint64_t>(k * kTurn);
    disturb();
    return true;
}

bool LoopSkipper::nothing_pending() const {
    const avr_cycle_timer_slot_t* due = m_avr->cycle_timers.timer;
    return avr_has_pending_interrupts(m_avr) == 0 && (due == nullptr || due->when > m_avr->cycle);
}

bool LoopSkipper::resume_on_proof() {
    return reuse_proof(m_avr->pc, sp(), cpu_state(), true);
}

void LoopSkipper::start_recording() {
    m_recording = true;
    m_footprint_known = true;
    m_recording_start = static_cast<Cycle>(m_avr->cycle);
    m_trace.steps.clear();
    m_trace.reads.clear();
    m_trace.writes.clear();
}

// The values the last step wrote: it has run now.
void LoopSkipper::end_step() {
    const std::size_t from = m_trace.steps.size() < 2 ? 0 : m_trace.steps[m_trace.steps.size() - 2].writes_end;
    for (std::size_t w = from; w < m_trace.writes.size(); ++w)
        m_trace.writes[w].second = m_avr->data[m_trace.writes[w].first];
}

void LoopSkipper::before_instruction() {
    if (!m_trace.steps.empty()) end_step();
    const std::uint32_t pc = m_avr->pc;
    if (pc + 3 >= m_avr->flashend) {
        m_footprint_known = false;
        return;
    }
    const DataAccesses accesses = data_accesses(flash_word(m_avr->flash, pc), flash_word(m_avr->flash, pc + 2), m_avr->data);
    if (accesses.unmodelled) m_footprint_known = false;
    TraceStep step{pc, static_cast<Cycle>(m_avr->cycle) - m_recording_start, cpu_state(), sp(), 0, 0};
    for (int i = 0; i < accesses.count; ++i) {
        const DataAccess& a = accesses.at[static_cast<std::size_t>(i)];
        if (a.addr >= m_snapshot.size()) {
            m_footprint_known = false;
            continue;
        }
        const bool io = a.addr >= 32 && a.addr < 32 + MAX_IOs;
        // A register with a read handler answers from outside the data space (PINx, UCSR0A).
        if (a.read && io && m_io[AVR_DATA_TO_IO(a.addr)].read != nullptr) m_footprint_known = false;
        if (a.read) m_trace.reads.emplace_back(a.addr, m_avr->data[a.addr]);
        if (a.write) m_trace.writes.emplace_back(a.addr, 0);
    }
    step.reads_end = static_cast<std::uint32_t>(m_trace.reads.size());
    step.writes_end = static_cast<std::uint32_t>(m_trace.writes.size());
    m_trace.steps.push_back(step);
}

bool LoopSkipper::keep_proof(Cycle period) {
    end_step();
    const std::vector<TraceStep>& steps = m_trace.steps;
    const std::size_t n = steps.size();
    const auto cpu_byte = [](std::uint16_t a) { return a < 32 || (a >= R_SPL && a <= R_SREG); };
    std::vector<std::int32_t>& read_col = m_read_column;
    std::vector<std::int32_t>& written_col = m_written_column;
    Proof p;
    for (const auto& [a, v] : m_trace.writes) {
        if (written_col[a] >= 0) continue;
        written_col[a] = static_cast<std::int32_t>(p.written.size());
        p.written.push_back(a);
    }
    for (const auto& [a, v] : m_trace.reads) {
        if (cpu_byte(a) || read_col[a] >= 0) continue;
        if (written_col[a] < 0) {
            read_col[a] = 0;
            p.read_only.emplace_back(a, v);  // unwritten: every read saw the same value
            continue;
        }
        read_col[a] = static_cast<std::int32_t>(p.rewritten.size());
        p.rewritten.push_back(a);
    }
    const std::size_t r = p.rewritten.size();
    const std::size_t w = p.written.size();
    const auto clear_columns = [&] {
        for (const auto& [a, v] : p.read_only) read_col[a] = -1;
        for (const std::uint16_t a : p.rewritten) read_col[a] = -1;
        for (const std::uint16_t a : p.written) written_col[a] = -1;
    };
    constexpr std::size_t kMaxCells = std::size_t{1} << 20;
    if (n * (r + w) > kMaxCells) {
        clear_columns();
        return false;
    }
    const auto reads_of = [&](std::size_t k) {
        return std::make_pair(k == 0 ? 0 : steps[k - 1].reads_end, steps[k].reads_end);
    };
    const auto writes_of = [&](std::size_t k) {
        return std::make_pair(k == 0 ? 0 : steps[k - 1].writes_end, steps[k].writes_end);
    };
    // First reads: two laps backwards; a step's reads come before its writes.
    std::vector<std::int16_t> next(r, -1);
    p.first_read.resize(n * r);
    for (std::size_t lap = 0; lap < 2; ++lap) {
        for (std::size_t k = n; k-- > 0;) {
            for (auto [x, e] = writes_of(k); x < e; ++x) {
                const std::uint16_t a = m_trace.writes[x].first;
                if (!cpu_byte(a) && read_col[a] >= 0) next[static_cast<std::size_t>(read_col[a])] = -1;
            }
            for (auto [x, e] = reads_of(k); x < e; ++x) {
                const auto [a, v] = m_trace.reads[x];
                if (!cpu_byte(a) && written_col[a] >= 0) next[static_cast<std::size_t>(read_col[a])] = v;
            }
            if (lap == 1)
                std::copy(next.begin(), next.end(), p.first_read.begin() + static_cast<std::ptrdiff_t>(k * r));
        }
    }
    // Last writes: two laps forwards.
    std::vector<std::uint8_t> value(w);
    std::vector<std::uint32_t> step(w);
    p.last_value.reserve(n * w);
    p.last_step.reserve(n * w);
    for (std::size_t lap = 0; lap < 2; ++lap) {
        for (std::size_t k = 0; k < n; ++k) {
            if (lap == 1) {
                p.last_value.insert(p.last_value.end(), value.begin(), value.end());
                p.last_step.insert(p.last_step.end(), step.begin(), step.end());
            }
            for (auto [x, e] = writes_of(k); x < e; ++x) {
                const auto [a, v] = m_trace.writes[x];
                const auto col = static_cast<std::size_t>(written_col[a]);
                value[col] = v;
                step[col] = static_cast<std::uint32_t>(k);
            }
        }
    }
    clear_columns();
    p.period = period;
    p.steps = steps;
    for (std::size_t k = 0; k < n; ++k) p.pcs.emplace_back(steps[k].pc, static_cast<std::uint32_t>(k));
    std::sort(p.pcs.begin(), p.pcs.end());
    count_pcs(m_proofs[m_next_proof], -1);
    count_pcs(p, 1);
    m_proofs[m_next_proof] = std::move(p);
    m_next_proof = (m_next_proof + 1) % m_proofs.size();
    return true;
}

void LoopSkipper::count_pcs(const Proof& p, int by) {
    for (std::size_t k = 0; k < p.pcs.size(); ++k) {
        if (k == 0 || p.pcs[k].first != p.pcs[k - 1].first) m_proof_pcs[p.pcs[k].first >> 1] += by;
    }
}

bool LoopSkipper::reuse_proof(std::uint32_t pc, std::uint16_t stack, const CpuState& cpu, bool anywhere) {
    if (m_proof_pcs[pc >> 1] == 0) return false;
    std::optional<Cycle> event;
    // Whether the CPU stands at boundary i of p and was moved on from there (with an interrupt pending or a cycle
    // timer due, event 0 moves it nowhere).
    const auto run_on = [&](const Proof& p, std::size_t i) {
        const TraceStep& s = p.steps[i];
        if (s.sp != stack || s.cpu != cpu) return false;
        if (!event) event = nothing_pending() ? m_quiet_until() : Cycle{0};
        return run_on_proof(p, i, *event);
    };
    const auto moved = [&](const Proof& p) {
        // Only the iteration's start, at a backward jump; after RETI, any of its boundaries.
        if (!anywhere) return p.steps[0].pc == pc && run_on(p, 0);
        const auto at = std::equal_range(p.pcs.begin(), p.pcs.end(), std::pair<std::uint32_t, std::uint32_t>{pc, 0},
                                         [](const auto& a, const auto& b) { return a.first < b.first; });
        return std::any_of(at.first, at.second, [&](const auto& entry) { return run_on(p, entry.second); });
    };
    for (const Proof& p : m_proofs) {
        if (p.steps.empty() || !moved(p)) continue;
        ++m_stats.reused;
        return true;
    }
    return false;
}

bool LoopSkipper::run_on_proof(const Proof& p, std::size_t i, Cycle event) {
    const std::size_t n = p.steps.size();
    if (p.period <= 0 || n == 0) return false;
    // The first instruction (counted on from boundary i, period after period) that ends at or past the event sees it:
    // the CPU goes to the boundary before it.
    const Cycle now = static_cast<Cycle>(m_avr->cycle);
    const Cycle begin = p.steps[i].offset;
    const Cycle x = event - now + begin;  // the event, counted from the iteration's start
    if (x <= begin) return false;
    const Cycle q = (x - 1) / p.period;
    const auto end_of = [&](std::size_t j) { return j + 1 < n ? p.steps[j + 1].offset : p.period; };
    std::size_t lo = 0;
    std::size_t hi = n - 1;
    while (lo < hi) {  // the first step of period q ending at or past x
        const std::size_t mid = (lo + hi) / 2;
        if (end_of(mid) + q * p.period >= x) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    const auto target = static_cast<std::size_t>(q) * n + lo;
    if (target <= i) return false;
    const std::size_t steps_on = target - i;
    // From boundary i round to it again, each byte whose first access is a read must hold what the proof read.
    for (const auto& [addr, value] : p.read_only) {
        if (m_avr->data[addr] != value) return false;
    }
    const std::size_t r = p.rewritten.size();
    const std::int16_t* first_read = p.first_read.data() + i * r;
    for (std::size_t c = 0; c < r; ++c) {
        if (first_read[c] >= 0 && m_avr->data[p.rewritten[c]] != first_read[c]) return false;
    }
    // Each byte written in the steps_on steps from boundary i holds its last write before the boundary reached.
    const std::size_t w = p.written.size();
    const std::uint8_t* last_value = p.last_value.data() + lo * w;
    const std::uint32_t* last_step = p.last_step.data() + lo * w;
    for (std::size_t c = 0; c < w; ++c) {
        if (steps_on >= n || (last_step[c] + n - i) % n < steps_on) m_avr->data[p.written[c]] = last_value[c];
    }
    const TraceStep& to = p.steps[lo];
    std::memcpy(m_avr->data, to.cpu.data(), 32);
    std::memcpy(m_avr->sreg, to.cpu.data() + 32, 8);
    m_avr->interrupt_state = static_cast<std::int8_t>(to.cpu[40]);
    m_avr->data[R_SPL] = static_cast<std::uint8_t>(to.sp & 0xFF);
    m_avr->data[R_SPH] = static_cast<std::uint8_t>(to.sp >> 8);
    m_avr->pc = to.pc;
    const Cycle skipped = to.offset + q * p.period - begin;
    m_avr->cycle += static_cast<avr_cycle_count_t>(skipped);
    ++m_stats.skips;
    m_stats.skipped_cycles += static_cast<std::uint64_t>(skipped);
    disturb();  // the watched loop's snapshot is of another state
    return true;
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
