#include "spi/core/spi_frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/bad_input.hpp"

namespace cnc::spi {

namespace {

void put_be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::uint32_t get_be32(const std::vector<std::uint8_t>& in, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | in[at + i];
    return v;
}

std::string period_error(std::uint64_t period, std::uint32_t min_period_cycles) {
    std::ostringstream s;
    if (period > kMaxPeriodCycles) {
        s << "period " << period << " clocks does not fit the rate word's 30-bit field (max " << kMaxPeriodCycles
          << " clocks)";
    } else {
        s << "period " << period << " clocks is shorter than the minimum STEP period of " << min_period_cycles
          << " clocks";
    }
    return s.str();
}

}  // namespace

std::uint32_t encode_rate_word(const AxisRate& rate, std::uint32_t min_period_cycles, const std::string& where) {
    // 0 = stopped: the FPGA ignores the direction bit then, but it is sent as given so that words round-trip.
    if (rate.period_cycles != 0 && (rate.period_cycles > kMaxPeriodCycles || rate.period_cycles < min_period_cycles))
        throw BadInput(where, period_error(rate.period_cycles, min_period_cycles));
    return rate.period_cycles | (rate.forward ? kDirForwardBit : 0U);
}

AxisRate decode_rate_word(std::uint32_t word) {
    return {word & kPeriodMask, (word & kDirForwardBit) != 0};
}

std::vector<std::uint8_t> encode_command(const Command& command, std::uint32_t min_period_cycles) {
    if (command.laser_on && command.axes.empty())
        throw std::invalid_argument("spi command: a laser bit needs the X rate word to carry it");
    std::vector<std::uint8_t> out;
    out.reserve(frame_bytes(command.axes.size()));
    out.push_back(kCmdRates);
    for (std::size_t i = 0; i < command.axes.size(); ++i) {
        std::uint32_t word =
            encode_rate_word(command.axes[i], min_period_cycles, "spi: rate word of axis " + std::to_string(i));
        if (i == 0 && command.laser_on) word |= kLaserOnBit;
        put_be32(out, word);
    }
    return out;
}

std::optional<Command> decode_command(const std::vector<std::uint8_t>& bytes, std::size_t n_axes) {
    if (bytes.size() != frame_bytes(n_axes) || bytes[0] != kCmdRates) return std::nullopt;
    Command command;
    command.axes.reserve(n_axes);
    for (std::size_t i = 0; i < n_axes; ++i) {
        const std::uint32_t word = get_be32(bytes, kHeaderBytes + 4 * i);
        command.axes.push_back(decode_rate_word(word));
        if (i == 0) command.laser_on = (word & kLaserOnBit) != 0;
    }
    return command;
}

std::uint8_t encode_status(const SlaveStatus& status) {
    const auto level = static_cast<std::uint8_t>(std::min<std::uint32_t>(status.fifo_level, kStatusLevelMask));
    return static_cast<std::uint8_t>(kStatusAlive | (status.rejected ? kStatusRejected : 0) |
                                     (status.dropped ? kStatusDropped : 0) | (status.fifo_full ? kStatusFull : 0) |
                                     level);
}

SlaveStatus decode_status(std::uint8_t byte) {
    SlaveStatus s;
    s.fifo_level = byte & kStatusLevelMask;
    s.fifo_full = (byte & kStatusFull) != 0;
    s.dropped = (byte & kStatusDropped) != 0;
    s.rejected = (byte & kStatusRejected) != 0;
    return s;
}

std::vector<std::uint8_t> encode_feedback(const Feedback& feedback) {
    std::vector<std::uint8_t> out;
    out.reserve(frame_bytes(feedback.counts.size()));
    out.push_back(encode_status(feedback.status));
    for (const std::int32_t c : feedback.counts) put_be32(out, static_cast<std::uint32_t>(c));
    return out;
}

Feedback decode_feedback(const std::vector<std::uint8_t>& bytes, std::size_t n_axes) {
    if (bytes.size() != frame_bytes(n_axes))
        throw std::invalid_argument("spi feedback: " + std::to_string(bytes.size()) + " bytes, expected " +
                                    std::to_string(frame_bytes(n_axes)));
    Feedback f;
    f.status = decode_status(bytes[0]);
    for (std::size_t i = 0; i < n_axes; ++i)
        f.counts.push_back(static_cast<std::int32_t>(get_be32(bytes, kHeaderBytes + 4 * i)));
    return f;
}

std::int64_t widen_count(std::int64_t previous, std::int32_t raw) {
    const auto diff = static_cast<std::uint32_t>(raw) - static_cast<std::uint32_t>(previous);
    return previous + static_cast<std::int32_t>(diff);
}

std::uint32_t period_for_rate(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                              const std::string& where) {
    if (!std::isfinite(steps_per_s)) throw BadInput(where, "step rate is not a finite number");
    const double rate = std::fabs(steps_per_s);
    if (rate == 0.0) return 0;
    const double clk = static_cast<double>(clk_hz);
    const double exact = clk / rate;
    std::ostringstream s;
    s.precision(10);
    if (exact >= static_cast<double>(kMaxPeriodCycles) + 0.5) {
        s << rate << " steps/s needs a period of " << exact << " clocks at " << clk_hz
          << " Hz, more than the rate word's 30-bit field holds (" << kMaxPeriodCycles
          << " clocks; slowest encodable rate " << clk / static_cast<double>(kMaxPeriodCycles) << " steps/s)";
        throw BadInput(where, s.str());
    }
    const auto period = static_cast<std::uint32_t>(std::llround(exact));
    if (period < std::max(min_period_cycles, 1U)) {  // a period of 0 would mean "stopped"
        s << rate << " steps/s needs a period of " << period << " clocks at " << clk_hz
          << " Hz, shorter than the minimum STEP period of " << min_period_cycles << " clocks (fastest rate "
          << clk / static_cast<double>(min_period_cycles) << " steps/s)";
        throw BadInput(where, s.str());
    }
    return period;
}

AxisRate axis_rate_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                       const std::string& where) {
    return {period_for_rate(steps_per_s, clk_hz, min_period_cycles, where), steps_per_s >= 0.0};
}

double rate_for_period(std::uint32_t period_cycles, std::uint32_t clk_hz) {
    return period_cycles == 0 ? 0.0 : static_cast<double>(clk_hz) / static_cast<double>(period_cycles);
}

}  // namespace cnc::spi
