// step_counter register (not in seed 004): counts STEP rising edges, +1 with DIR high, -1 with DIR low, in a signed
// 32-bit register that wraps. It detects the rise from the STEP register's output, so a STEP rise at edge n
// updates the count at edge n + 1, and a register that loads the count at edge m (the SPI snapshot) captures
// every STEP rise at edges <= m - 2. This class answers "what does a load at edge m capture" for m >= the
// latest update edge - 2, keeping only the last few updates (rises are >= 2 edges apart).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace cnc::fpga {

class StepCountHistory {
public:
    // STEP rose at edge `rise_edge` with DIR at `forward`.
    void add_rise(std::int64_t rise_edge, bool forward);
    [[nodiscard]] std::int32_t value_at_edge(std::int64_t edge) const;
    [[nodiscard]] std::int32_t value() const { return m_value; }  // after every update seen so far
    [[nodiscard]] std::uint64_t forward_rises() const { return m_forward; }
    [[nodiscard]] std::uint64_t reverse_rises() const { return m_reverse; }

private:
    static constexpr std::size_t kKept = 4;
    struct Update {
        std::int64_t edge = 0;
        std::int32_t value = 0;  // register value from this edge on
    };
    std::array<Update, kKept> m_recent{};  // ring, oldest overwritten
    std::size_t m_size = 0;
    std::size_t m_next = 0;
    std::int32_t m_before_recent = 0;  // value before the oldest kept update
    std::int32_t m_value = 0;
    std::uint64_t m_forward = 0;
    std::uint64_t m_reverse = 0;
};

}  // namespace cnc::fpga
