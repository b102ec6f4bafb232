#include "uart/core/line_receiver.hpp"

namespace cnc::uart {

TimePs decision_offset_ps(BitClock clk, const FrameFormat& fmt) {
    return clk.mid_bit(fmt.bits_per_frame() - 1);
}

RxFrame receive_frame(const EdgeLog& line, TimePs t_fall_ps, BitClock clk, const FrameFormat& fmt) {
    validate(fmt);
    RxFrame out;
    out.t_decision_ps = t_fall_ps + decision_offset_ps(clk, fmt);
    out.t_stop_end_ps = t_fall_ps + frame_time_ps(clk, fmt);
    const auto sample = [&](int k) { return line.level_at(t_fall_ps + clk.mid_bit(k)); };

    if (sample(0)) {
        out.status = RxStatus::FalseStart;
        return out;
    }
    int ones = 0;
    for (int i = 0; i < fmt.data_bits; ++i) {
        if (sample(1 + i)) {
            out.byte = static_cast<std::uint8_t>(out.byte | (1U << i));
            ++ones;
        }
    }
    int k = 1 + fmt.data_bits;
    if (fmt.parity != Parity::None) {
        const bool parity_bit = sample(k++);
        const bool total_odd = ((ones + (parity_bit ? 1 : 0)) % 2) != 0;
        if (total_odd != (fmt.parity == Parity::Odd)) out.status = RxStatus::ParityError;
    }
    for (int s = 0; s < fmt.stop_bits; ++s) {
        if (!sample(k++)) out.status = RxStatus::FramingError;
    }
    return out;
}

}  // namespace cnc::uart
