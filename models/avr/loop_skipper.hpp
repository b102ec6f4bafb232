// Fast-forward over a polling loop (AvrCoreConfig::fast_forward): when the CPU runs a loop whose iterations leave
// the whole machine as they found it, whole iterations are skipped up to the next event the CPU could see, by
// advancing the cycle count alone. Exact: every interrupt, flag and pin edge comes at the same cycle as without it.
//
// An iteration is the span between two visits of a backward-jump target (the watched loop: a target whose last two
// visits looked alike). It is proven idle when, between the watched target's last two visits, the registers, SREG,
// the stack pointer, the interrupt state and every byte of the data space (I/O and SRAM) are equal and nothing
// disturbed: no I/O register with effects was read or written (reads of PINx, UCSR0A and handler-less registers such
// as TIFRn have none, and their values change only at events), no interrupt was taken, no timer or USART event the
// CPU can see happened (a flag raised that was clear or enabled, a USART event, an output pin change while the loop
// reads PINx), no other cycle timer fell due and no input changed. The same iteration from the same state runs the
// same way, so the skip ends before the first such event (the chip's quiet_until: the run_until boundary, simavr's
// cycle timers, the USART's next event, and the timers' coming events, probed on copies of the units). Events that
// change nothing (a free-running timer setting a flag that is already set, its interrupt off) pass during a skip and
// are processed, at their own cycles, right after it.
//
// A proof is kept and used again, instruction by instruction: while the watched loop's iteration runs, the CPU
// before each instruction and the data bytes it reads and writes, with their values, are noted (core/data_access.hpp).
// From any of its instruction boundaries, the iteration depends on the registers, SREG, SP, the interrupt state and
// the bytes it reads before writing them, and changes only the bytes it writes. Where the CPU stands at such a
// boundary after an interrupt changed bytes it does not read (grbl's stepper interrupt: its counters and positions,
// while the main loop polls its flags), with no interrupt pending, equal registers and equal read bytes make the
// iteration the proven one: the CPU is moved on to the instruction that sees the next event, and the bytes written on
// the way take their last written values. An iteration that reads an I/O register with a read handler or runs an
// instruction acting beyond the data space (SLEEP, WDR, SPM, BREAK) is not kept. avr-libc's busy delay loop (SBIW,
// BRNE: never idle, its counter changes) is skipped turn by turn.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "avr/core/prescaler.hpp"

struct avr_t;

namespace cnc::avr {

// The flash word at byte address `a` (little-endian: an opcode, or a 32-bit instruction's second word).
[[nodiscard]] inline std::uint16_t flash_word(const std::uint8_t* flash, std::uint32_t a) {
    return static_cast<std::uint16_t>(flash[a] | (flash[a + 1] << 8));
}

struct FastForwardStats {
    std::uint64_t skips = 0;           // loops fast-forwarded
    std::uint64_t skipped_cycles = 0;  // cycles not executed
    std::uint64_t reused = 0;          // skips on a kept proof, without running a proving iteration
};

class LoopSkipper {
public:
    // Watches every I/O register of `avr` that has a handler (install it after the chip's own handlers): a read of
    // one of `pins` (PINx) or `pure_reads` has no effect and its value changes only at events; any other access
    // disturbs. `quiet_until()`: the first cycle at which something the CPU can see may happen (a cycle timer, a
    // flag, an input, an output pin if pins_read()); the skips end before it.
    LoopSkipper(avr_t* avr, const std::vector<std::uint16_t>& pins, const std::vector<std::uint16_t>& pure_reads,
                std::function<Cycle()> quiet_until);
    ~LoopSkipper();
    LoopSkipper(const LoopSkipper&) = delete;
    LoopSkipper& operator=(const LoopSkipper&) = delete;

    // Something the data space does not show happened (an I/O access with effects, an interrupt, a cycle timer, an
    // input or a received frame): the iterations seen so far prove nothing.
    void disturb() {
        ++m_epoch;
        m_pins_read = false;
        m_recording = false;
    }
    // Whether a PINx was read since the last disturbance: a loop that reads none does not see its output pins, so
    // their changes do not disturb it.
    [[nodiscard]] bool pins_read() const { return m_pins_read; }
    // After a simavr step that left the CPU running at a program counter not above the one it started at (a
    // backward jump, a jump to itself, an interrupt's vector, a return to an earlier address).
    void backward_jump();
    // Whether the chip must call before_instruction() before each instruction (a proving iteration runs).
    [[nodiscard]] bool recording() const { return m_recording; }
    void before_instruction();
    // Where the CPU may be inside a proven iteration, running with no interrupt pending (after a RETI and the
    // instruction that follows it, at the start of a run): moves it on when it is. Whether it did.
    bool resume_on_proof();
    [[nodiscard]] const FastForwardStats& stats() const { return m_stats; }

private:
    static constexpr std::size_t kCpuBytes = 32 + 8 + 1;  // r0..r31, SREG's bits, the interrupt state
    using CpuState = std::array<std::uint8_t, kCpuBytes>;
    struct Visit {
        std::uint32_t pc = UINT32_MAX;
        Cycle cycle = 0;
        std::uint64_t epoch = 0;
        std::uint16_t sp = 0;
        CpuState cpu{};
    };

    struct Io;  // the handlers the watch replaced (loop_skipper.cpp)

    // One instruction of a proving iteration: where it starts (cycles from the iteration's start), the CPU before
    // it, and where its reads and writes end in the trace's lists (they start where the previous step's end).
    struct TraceStep {
        std::uint32_t pc = 0;
        Cycle offset = 0;
        CpuState cpu{};
        std::uint16_t sp = 0;
        std::uint32_t reads_end = 0;
        std::uint32_t writes_end = 0;
    };
    // The proving iteration as it runs.
    struct Trace {
        std::vector<TraceStep> steps;
        std::vector<std::pair<std::uint16_t, std::uint8_t>> reads;   // with the value read
        std::vector<std::pair<std::uint16_t, std::uint8_t>> writes;  // with the value written
    };
    // An iteration proven idle, instruction by instruction: any of its instruction boundaries, met again with the
    // same CPU and the same bytes it reads before writing them from there on, runs it again. Its tables have a row
    // per instruction boundary j (n = steps.size() rows) and a column per byte. The registers, SP and SREG are the
    // CPU's, compared apart (instructions move them without a write).
    struct Proof {
        Cycle period = 0;
        std::vector<TraceStep> steps;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pcs;  // (pc, step), sorted: searched after RETI
        // The bytes the iteration reads and never writes, with the value read: from any boundary they must hold it.
        std::vector<std::pair<std::uint16_t, std::uint8_t>> read_only;
        // The bytes it reads and writes; from boundary j on, the value its first access reads (-1: it is a write).
        std::vector<std::uint16_t> rewritten;
        std::vector<std::int16_t> first_read;
        // The bytes it writes (the CPU's too): at boundary j, each one's last write before it, counted back round
        // the turn, and that write's step.
        std::vector<std::uint16_t> written;
        std::vector<std::uint8_t> last_value;
        std::vector<std::uint32_t> last_step;
    };

    [[nodiscard]] CpuState cpu_state() const;
    [[nodiscard]] std::uint16_t sp() const;
    // Iterations of `period` skipped before the next event the CPU could see (0: none).
    Cycle skip(Cycle period);
    // No interrupt waiting (for SEI: it would be taken where no skipped turn took one) and no cycle timer due (an
    // event still to process): the CPU may be moved on from here.
    [[nodiscard]] bool nothing_pending() const;
    void start_recording();
    void end_step();
    // Keeps the iteration just proven; false when its tables would be too large.
    bool keep_proof(Cycle period);
    void count_pcs(const Proof& p, int by);
    bool skip_delay_loop();
    // From the proof's instruction boundary i, where the CPU is now: when the bytes the iteration reads from there
    // on are as then, the CPU is moved to the boundary of the instruction that sees `event` (the next event).
    bool run_on_proof(const Proof& p, std::size_t i, Cycle event);
    bool reuse_proof(std::uint32_t pc, std::uint16_t stack, const CpuState& cpu, bool anywhere);
    avr_t* m_avr;
    std::function<Cycle()> m_quiet_until;
    std::vector<Io> m_io;  // by I/O register index
    std::uint64_t m_epoch = 0;
    bool m_pins_read = false;
    std::array<Visit, 16> m_visits{};  // by backward-jump target
    // The watched loop: its target's last visit, and the data space then; the next visit that finds them again
    // proves the iteration idle.
    Visit m_loop;
    std::vector<std::uint8_t> m_snapshot;
    // keep_proof's columns by data address (-1: none), all -1 between calls.
    std::vector<std::int32_t> m_read_column;
    std::vector<std::int32_t> m_written_column;
    // The proving iteration: whether one runs, whether every byte it touched is known, its steps so far.
    bool m_recording = false;
    bool m_footprint_known = false;
    Cycle m_recording_start = 0;
    Trace m_trace;
    std::array<Proof, 4> m_proofs{};
    std::vector<int> m_proof_pcs;  // by flash word: how many kept proofs have an instruction there
    std::size_t m_next_proof = 0;
    FastForwardStats m_stats;
};

}  // namespace cnc::avr
