#include "architectures/fpga_uart/dead_time.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <limits>

#include <nlohmann/json.hpp>

#include "host/core/packet_codec.hpp"

namespace cnc::sim {

namespace {

double mean_ms(const DeadTimeBreakdown& d, TimePs GapBreakdown::*part) {
    if (d.gap_count == 0) return 0.0;
    return static_cast<double>(d.sum.*part) / static_cast<double>(d.gap_count) / static_cast<double>(kPsPerMs);
}

double max_ms(const DeadTimeBreakdown& d, TimePs GapBreakdown::*part) {
    return static_cast<double>(d.max.*part) / static_cast<double>(kPsPerMs);
}

struct Part {
    const char* name;
    TimePs GapBreakdown::*field;
};

constexpr Part kParts[] = {{"step_tail", &GapBreakdown::step_tail_ps},
                           {"ack_wire", &GapBreakdown::ack_wire_ps},
                           {"usb_in", &GapBreakdown::usb_in_ps},
                           {"job_wait", &GapBreakdown::job_wait_ps},
                           {"host", &GapBreakdown::host_ps},
                           {"usb_out", &GapBreakdown::usb_out_ps},
                           {"packet_wire", &GapBreakdown::packet_wire_ps},
                           {"fpga_setup", &GapBreakdown::fpga_setup_ps},
                           {"total", &GapBreakdown::total_ps}};

void add_gap(DeadTimeBreakdown& d, const GapBreakdown& g, bool keep_gaps) {
    ++d.gap_count;
    for (const Part& p : kParts) {
        d.sum.*p.field += g.*p.field;
        d.max.*p.field = std::max(d.max.*p.field, g.*p.field);
    }
    if (keep_gaps) d.gaps.push_back(g);
}

}  // namespace

PieceSteps piece_steps(const metrics::MoveMetrics& piece) {
    return {piece.t_first_edge_ps, piece.t_last_edge_ps};
}

void DeadTimeFold::fold(TimePs now_ps, bool ended, const fpga::Board& fpga, const RecordLog<host::SentPacket>& sent,
                        const uart::Cp2102& cp2102) {
    const auto& first_bytes = cp2102.tx_log();  // [k] motion packet k's first byte
    const auto& rx = cp2102.rx_log();
    for (;; ++m_next_gap) {
        const std::size_t i = m_next_gap;
        // Inputs still to come: wait for them, or at the end leave this and every later gap out.
        if (i + 1 >= m_first_piece + m_pieces.size() || i + 1 >= sent.size() || i + 1 >= fpga.packet_count()) break;
        const fpga::PacketRecord done = fpga.packet(i);
        if (!ended && done.accepted && now_ps <= done.t_busy_fall_ps) break;
        const PieceSteps& piece_a = m_pieces[i - m_first_piece];
        const PieceSteps& piece_b = m_pieces[i + 1 - m_first_piece];
        if (done.t_ack_start_ps < 0 || sent[i + 1].t_write_ps < 0) continue;
        if (i + 1 >= first_bytes.size()) {
            if (ended) continue;
            break;
        }
        const TimePs next_start_bit_ps = first_bytes[i + 1].t_start_bit_ps;
        // The bytes are in time order: a binary search keeps a long job's gaps linear.
        const auto ack = std::partition_point(rx.begin(), rx.end(), [&](const uart::Cp2102::RxByte& b) {
            return b.t_start_bit_ps < done.t_ack_start_ps;
        });
        if (ack == rx.end()) {
            if (ended) continue;
            break;
        }
        m_next_rx_byte = rx.first() + static_cast<std::size_t>(std::distance(rx.begin(), ack));
        if (!piece_a.t_last_ps || !piece_b.t_first_ps) continue;
        const fpga::PacketRecord next = fpga.packet(i + 1);
        const TimePs last_a = *piece_a.t_last_ps;
        const TimePs first_b = *piece_b.t_first_ps;
        GapBreakdown g;
        g.after_packet = static_cast<int>(i) + 1;
        g.step_tail_ps = done.t_busy_fall_ps - last_a;
        g.ack_wire_ps = ack->t_stop_end_ps - done.t_busy_fall_ps;
        g.usb_in_ps = ack->t_host_visible_ps - ack->t_stop_end_ps;
        g.job_wait_ps = sent[i + 1].wait_before_ps;
        g.host_ps = sent[i + 1].t_write_ps - ack->t_host_visible_ps - g.job_wait_ps;
        g.usb_out_ps = next_start_bit_ps - sent[i + 1].t_write_ps;
        g.packet_wire_ps = next.t_pkt_valid_ps - next_start_bit_ps;
        g.fpga_setup_ps = first_b - next.t_pkt_valid_ps;
        g.total_ps = first_b - last_a;
        add_gap(m_d, g, m_keep_gaps);
    }
    // Gap m_next_gap reads its own piece and the next one: the ones before are done with.
    while (m_first_piece < m_next_gap && !m_pieces.empty()) {
        m_pieces.pop_front();
        ++m_first_piece;
    }
}

DeadTimeBreakdown DeadTimeFold::finish(TimePs t_job_start_ps, TimePs t_job_end_ps, const uart::Cp2102& cp2102) {
    const TimePs job = t_job_end_ps - t_job_start_ps;
    if (job > 0) {
        const TimePs busy_to = cp2102.stats().tx_line_busy_ps;
        const TimePs busy_from = cp2102.stats().rx_line_busy_ps;
        m_d.utilisation_to_fpga_pct = 100.0 * static_cast<double>(busy_to) / static_cast<double>(job);
        m_d.utilisation_from_fpga_pct = 100.0 * static_cast<double>(busy_from) / static_cast<double>(job);
    }
    return m_d;
}

nlohmann::json to_json(const DeadTimeBreakdown& d, bool detail) {
    nlohmann::json mean = nlohmann::json::object();
    nlohmann::json max = nlohmann::json::object();
    for (const Part& p : kParts) {
        mean[std::string(p.name) + "_ms"] = mean_ms(d, p.field);
        max[std::string(p.name) + "_ms"] = max_ms(d, p.field);
    }
    nlohmann::json j = {{"gaps", d.gap_count}, {"mean", mean}, {"max", max}};
    if (!detail) return j;
    nlohmann::json gaps = nlohmann::json::array();
    for (const GapBreakdown& g : d.gaps) {
        nlohmann::json row = {{"after_packet", g.after_packet}};
        for (const Part& p : kParts) row[std::string(p.name) + "_us"] = static_cast<double>(g.*p.field) / kPsPerUs;
        gaps.push_back(row);
    }
    j["per_gap"] = std::move(gaps);
    return j;
}

std::vector<GapCauses> gap_causes(const DeadTimeBreakdown& d) {
    std::vector<GapCauses> out;
    for (const GapBreakdown& g : d.gaps) {
        GapCauses c;
        c.after_piece = static_cast<std::size_t>(g.after_packet - 1);
        for (const Part& p : kParts) {
            if (p.field == &GapBreakdown::total_ps) continue;
            c.parts_ms.emplace_back(p.name, static_cast<double>(g.*p.field) / static_cast<double>(kPsPerMs));
        }
        out.push_back(std::move(c));
    }
    return out;
}

std::string summary_text(const DeadTimeBreakdown& d) {
    std::string out = "  dead time between packets (" + std::to_string(d.gap_count) + " gaps), ms: mean      max\n";
    for (const Part& p : kParts) {
        char line[96];
        std::snprintf(line, sizeof line, "    %-12s %28.4f %8.4f\n", p.name, mean_ms(d, p.field), max_ms(d, p.field));
        out += line;
    }
    char util[96];
    std::snprintf(util, sizeof util, "  line utilisation: host->FPGA %.3f %%, FPGA->host %.3f %%\n",
                  d.utilisation_to_fpga_pct, d.utilisation_from_fpga_pct);
    return out + util;
}

}  // namespace cnc::sim
