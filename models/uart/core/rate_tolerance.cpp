#include "uart/core/rate_tolerance.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::uart {

double stop_sample_bits(const FrameFormat& fmt) {
    const int before_stop = 1 + fmt.data_bits + (fmt.parity == Parity::None ? 0 : 1);  // start, data, parity
    return before_stop + 0.5;  // the middle of the first stop bit
}

double max_rate_mismatch(const FrameFormat& fmt) {
    constexpr double kHalfBit = 0.5;        // the sample may drift half a bit before it leaves the stop bit
    constexpr double kMarginDivisor = 2.0;  // half the budget, for real edges and receivers (header)
    return kHalfBit / stop_sample_bits(fmt) / kMarginDivisor;
}

double rate_mismatch(double a_bd, double b_bd) {
    return a_bd / b_bd - 1.0;
}

bool rates_within_tolerance(double a_bd, double b_bd, const FrameFormat& fmt) {
    const double worst = std::max(std::fabs(rate_mismatch(a_bd, b_bd)), std::fabs(rate_mismatch(b_bd, a_bd)));
    return worst <= max_rate_mismatch(fmt);
}

}  // namespace cnc::uart
