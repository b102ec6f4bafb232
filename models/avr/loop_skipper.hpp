// Fast-forward over a polling loop (AvrCoreConfig::fast_forward): when the CPU runs a loop whose iterations leave
// the whole machine as they found it, whole iterations are skipped up to the next event, by advancing the cycle count
// alone. Exact: a skip ends before the next cycle timer (our timer and USART scheduler, simavr's own peripherals,
// the run_until boundary), so every interrupt, flag and pin edge comes at the same cycle as without it.
//
// An iteration is the span between two visits of the same backward-jump target. A loop is proven idle when, between
// its last two visits: the registers, SREG, the stack pointer, the interrupt state and every byte of the data space
// (I/O and SRAM) are equal, no I/O register with effects was read or written (only PINx, UCSR0A and handler-less
// registers such as TIFRn are read without effect, and their values change only at events), no interrupt was taken
// and no cycle timer fell due. Repeating an iteration from the same state with the same inputs gives the same
// iteration, so the next ones up to the next event are the same too.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "avr/core/prescaler.hpp"

struct avr_t;

namespace cnc::avr {

struct FastForwardStats {
    std::uint64_t skips = 0;           // loops fast-forwarded
    std::uint64_t skipped_cycles = 0;  // cycles not executed
};

class LoopSkipper {
public:
    // Watches every I/O register of `avr` that has a handler (install it after the chip's own handlers): a read of
    // one of `pure_reads` has no effect and its value changes only at events; any other access disturbs.
    LoopSkipper(avr_t* avr, const std::vector<std::uint16_t>& pure_reads);
    ~LoopSkipper();
    LoopSkipper(const LoopSkipper&) = delete;
    LoopSkipper& operator=(const LoopSkipper&) = delete;

    // Something the data space does not show happened (an I/O access with effects, an interrupt, a cycle timer, an
    // input or a received frame): the iterations seen so far prove nothing.
    void disturb() { ++m_epoch; }
    // After one simavr step that started at program counter pc_before (bytes).
    void after_step(std::uint32_t pc_before);
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

    [[nodiscard]] CpuState cpu_state() const;
    [[nodiscard]] std::uint16_t sp() const;
    void skip(Cycle period);

    avr_t* m_avr;
    std::vector<Io> m_io;  // by I/O register index
    std::uint64_t m_epoch = 0;
    std::array<Visit, 16> m_visits{};  // by backward-jump target
    // The data space at the last visit of a loop whose two visits before matched (armed): the next visit compares.
    std::vector<std::uint8_t> m_snapshot;
    std::uint32_t m_armed_pc = UINT32_MAX;
    Cycle m_armed_period = 0;
    std::uint64_t m_armed_epoch = 0;
    FastForwardStats m_stats;
};

}  // namespace cnc::avr
