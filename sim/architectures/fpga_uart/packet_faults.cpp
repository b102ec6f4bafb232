#include "architectures/fpga_uart/packet_faults.hpp"

#include <algorithm>
#include <iterator>
#include <optional>

namespace cnc::sim::fpga_uart {

namespace {

constexpr std::uint8_t kMotionBits = 0x3;  // packet_decoder keeps b0[1:0] (seed 000 §5.2.3)

bool same(const fpga::MotionFields& a, const fpga::MotionFields& b) {
    return (a.motion & kMotionBits) == (b.motion & kMotionBits) && a.steps_x == b.steps_x && a.steps_y == b.steps_y &&
           a.feed == b.feed && a.laser_high == b.laser_high;
}

// Stop-and-wait: the packet the host was sending when the record arrived, the last it took before.
std::optional<std::size_t> in_flight_when(const std::vector<HostPacket>& sent, const FpgaPacket& r) {
    const auto after = std::upper_bound(sent.begin(), sent.end(), r.t_pkt_valid_ps,
                                        [](TimePs t, const HostPacket& p) { return t < p.t_taken_ps; });
    if (after == sent.begin()) return std::nullopt;
    return static_cast<std::size_t>(std::distance(sent.begin(), after) - 1);
}

std::optional<std::size_t> in_turn(const std::vector<HostPacket>& sent, std::size_t run) {
    if (run >= sent.size()) return std::nullopt;
    return run;
}

}  // namespace

PacketFaults packet_faults(const std::vector<HostPacket>& sent, const std::vector<FpgaPacket>& received,
                           bool in_order) {
    PacketFaults f;
    std::size_t run = 0;
    f.sent = static_cast<std::int64_t>(sent.size());
    std::vector<int> runs_as_sent(sent.size(), 0);
    std::vector<bool> run_wrong(sent.size(), false);
    for (const HostPacket& p : sent) {
        f.job_end_error_steps[0] -= p.fields.steps_x;
        f.job_end_error_steps[1] -= p.fields.steps_y;
    }
    for (const FpgaPacket& r : received) {
        if (!r.accepted) {
            ++f.ignored;
            continue;
        }
        f.job_end_error_steps[0] += r.fields.steps_x;
        f.job_end_error_steps[1] += r.fields.steps_y;
        const std::optional<std::size_t> paired = in_order ? in_turn(sent, run++) : in_flight_when(sent, r);
        if (!paired) {  // bytes before the first packet, or more runs than packets
            ++f.extra;
            continue;
        }
        const std::size_t k = *paired;
        const HostPacket& p = sent[k];
        if (same(r.fields, p.fields)) {
            if (runs_as_sent[k]++ > 0) ++f.extra;
            continue;
        }
        ++f.executed_wrong;
        run_wrong[k] = true;
        f.silent.push_back(
            {static_cast<int>(k) + 1,
             p.gcode_line,
             p.fields,
             r.fields,
             {std::int64_t{r.fields.steps_x} - p.fields.steps_x, std::int64_t{r.fields.steps_y} - p.fields.steps_y}});
    }
    for (std::size_t k = 0; k < sent.size(); ++k) {
        if (runs_as_sent[k] > 0)
            ++f.executed_as_sent;
        else if (!run_wrong[k])
            ++f.lost;
    }
    return f;
}

}  // namespace cnc::sim::fpga_uart
