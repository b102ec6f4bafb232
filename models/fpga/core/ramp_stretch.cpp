#include "fpga/core/ramp_stretch.hpp"

namespace cnc::fpga {

namespace {

__extension__ typedef unsigned __int128 Wide;

constexpr std::uint64_t kTruncation = std::uint64_t{1} << kJerkShift;

// Over m = 0 .. n-1, with q(m) = floor((a m + b) / c): the sums of q, m q and q^2.
struct FloorSums {
    Wide q = 0;
    Wide mq = 0;
    Wide qq = 0;
};

// Euclid's algorithm on (a, c). Whole multiples of c in a or b come out as sums of powers of m. Otherwise q(m) counts
// the rows j < q(m), and row j holds the m past t(j) = floor((c j + c - b - 1) / a): counted by rows, the sums are
// those of t over j < q(n - 1) with a and c swapped, a smaller problem. Each sum stays below n^2 qmax (qmax the
// largest q(m)) and qmax^3.
FloorSums floor_sums(std::uint64_t n, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    if (n == 0) return {};
    const Wide wn = n;
    const Wide sum_m = wn * (wn - 1) / 2;
    if (a >= c || b >= c) {
        const Wide qa = a / c;
        const Wide qb = b / c;
        const FloorSums r = floor_sums(n, a % c, b % c, c);
        const Wide sum_m2 = qa == 0 ? 0 : sum_m * (2 * wn - 1) / 3;
        return {r.q + qa * sum_m + qb * wn, r.mq + qa * sum_m2 + qb * sum_m,
                r.qq + qa * qa * sum_m2 + 2 * qa * qb * sum_m + qb * qb * wn + 2 * qa * r.mq + 2 * qb * r.q};
    }
    const Wide rows = (Wide{a} * (n - 1) + b) / c;
    if (rows == 0) return {};
    const FloorSums t = floor_sums(static_cast<std::uint64_t>(rows), c, c - b - 1, a);
    // Row j holds n - 1 - t(j) points, at m = t(j) + 1 .. n - 1; q^2 is the sum of 2 j + 1 over its rows.
    return {rows * (wn - 1) - t.q, (rows * wn * (wn - 1) - t.qq - t.q) / 2, (wn - 1) * rows * rows - 2 * t.mq - t.q};
}

}  // namespace

std::int64_t stretch_increment(const RampStretch& s, std::int64_t m) {
    // Modulo 2^64: a falling acceleration's jerk wraps round, and the product may pass 2^63 where the sum does not.
    const std::uint64_t accel = s.accel + static_cast<std::uint64_t>(s.jerk) * static_cast<std::uint64_t>(m);
    const auto increment = static_cast<std::int64_t>(accel / kTruncation);
    return s.slowing ? -increment : increment;
}

RampGain stretch_gain(const RampStretch& s, std::int64_t n) {
    if (n == 0) return {};
    const auto clocks = static_cast<std::uint64_t>(n);
    RampGain g;
    if (s.jerk >= 0) {
        const FloorSums f = floor_sums(clocks, static_cast<std::uint64_t>(s.jerk), s.accel, kTruncation);
        g.velocity = static_cast<RampWide>(f.q);
        g.phase = n * g.velocity - static_cast<RampWide>(f.mq);
    } else {
        // A falling acceleration read from the stretch's clock n - 1 back: its clock n - 1 - m weighs m + 1.
        const auto fall = static_cast<std::uint64_t>(-s.jerk);
        const FloorSums f = floor_sums(clocks, fall, s.accel - fall * (clocks - 1), kTruncation);
        g.velocity = static_cast<RampWide>(f.q);
        g.phase = static_cast<RampWide>(f.mq + f.q);
    }
    if (s.slowing) {
        g.velocity = -g.velocity;
        g.phase = -g.phase;
    }
    return g;
}

}  // namespace cnc::fpga
