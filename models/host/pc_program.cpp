#include "host/pc_program.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "common/sc_time.hpp"

namespace cnc::host {

namespace {

constexpr double kConfirmedBytesPerTrip = 2.0;  // the byte and its confirm

std::string hex_byte(std::uint8_t b) {
    char text[8];
    std::snprintf(text, sizeof text, "%02X", b);
    return text;
}

// The bytes as a C string literal: printable ASCII as it is, the usual escapes, \xNN for the rest.
std::string as_text(const std::vector<std::uint8_t>& bytes) {
    std::string out = "\"";
    for (const std::uint8_t b : bytes) {
        if (b == '\r') {
            out += "\\r";
        } else if (b == '\n') {
            out += "\\n";
        } else if (b == '\t') {
            out += "\\t";
        } else if (b == '"' || b == '\\') {
            out += std::string("\\") + static_cast<char>(b);
        } else if (b >= 0x20 && b < 0x7F) {
            out += static_cast<char>(b);
        } else {
            out += "\\x" + hex_byte(b);
        }
    }
    return out + "\"";
}

std::string as_hex(const std::vector<std::uint8_t>& bytes) {
    std::string out;
    for (const std::uint8_t b : bytes) out += (out.empty() ? "" : " ") + hex_byte(b);
    return out;
}

std::string ms_text(TimePs t_ps) {
    return fmt::format(FMT_STRING("{:.1f} ms"), static_cast<double>(t_ps) / kPsPerMs);
}

}  // namespace

TimePs byte_round_trip_ps(const SenderConfig& cfg, const uart::Cp2102Config& link) {
    const double line_s =
        kConfirmedBytesPerTrip * link.format.bits_per_frame() / static_cast<double>(link.requested_baud);
    return cfg.write_latency_ps + 2 * link.usb_frame_ps + link.usb_latency_ps + s_to_ps(line_s);
}

PcProgram::PcProgram(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
                     std::vector<cad2g::Transfer> transfers, ConfirmTimeouts timeouts)
    : sc_module(name),
      m_cfg(cfg),
      m_port(port),
      m_transfers(std::move(transfers)),
      m_timeouts(std::move(timeouts)),
      m_stall(cfg.stall) {
    for (const cad2g::Transfer& t : m_transfers) m_job_bytes += t.bytes.size();
    SC_HAS_PROCESS(PcProgram);
    SC_THREAD(run);
}

void PcProgram::set_waits(const UnitWaits& waits) {
    m_waits = waits;
}

std::string PcProgram::place_after(std::size_t written) const {
    if (written == 0) return "before the job's first byte (after the port settled)";
    return "after writing the job's byte " + std::to_string(written) + " of " + std::to_string(m_job_bytes);
}

void PcProgram::stall_if_due() {
    if (const TimePs wait = m_stall.wait_at(now_ps())) wait_ps(wait);
}

bool PcProgram::wait_for_confirm(TimePs deadline_ps, TimePs timeout_ps, const std::string& place) {
    stall_if_due();
    while (m_port.in_waiting() == 0) {
        const TimePs now = now_ps();
        if (now >= deadline_ps) {
            const std::string why = m_writes.empty() ? "the firmware does not speak the seed 003 protocol"
                                                     : "the firmware stopped answering";
            m_failure =
                LinkFailure{now, "no confirm byte 0x06 within " + ms_text(timeout_ps) + " " + place + ": " + why};
            return false;
        }
        sc_core::wait(ps_time(deadline_ps - now), m_port.data_event());
        stall_if_due();
    }
    const std::uint8_t b = *m_port.read_byte();
    if (b == cad2g::kConfirmByte) return true;
    stop_on_mismatch(b, place);
    return false;
}

void PcProgram::stop_on_mismatch(std::uint8_t first, const std::string& place) {
    const TimePs t_first = now_ps();
    // Long enough for kShownBytes more to cross the line and reach the program.
    const TimePs listen_until = t_first + m_timeouts.round_trip_ps +
                                static_cast<TimePs>(kShownBytes) * uart::frame_time_ps(m_port.baud().bit_clock());
    std::vector<std::uint8_t> got{first};
    while (got.size() < kShownBytes) {
        if (m_port.in_waiting() > 0) {
            got.push_back(*m_port.read_byte());
            continue;
        }
        const TimePs now = now_ps();
        if (now >= listen_until) break;
        sc_core::wait(ps_time(listen_until - now), m_port.data_event());
    }
    const std::string more = m_port.in_waiting() > 0 ? ", the first " + std::to_string(got.size()) : "";
    m_failure = LinkFailure{t_first, "protocol mismatch: expected the confirm byte 0x06 of the seed 003 protocol " +
                                         place + ", received " + as_text(got) + " (hex " + as_hex(got) + more + ")"};
}

void PcProgram::run() {
    m_port.reset_input_buffer();  // PurgeComm(RX | TX) comes before the Sleep (seed 003 §5.3.2)
    wait_ps(m_cfg.settle_ps);
    TimePs timeout_ps = m_timeouts.round_trip_ps + kConfirmMarginPs;
    TimePs deadline_ps = now_ps() + timeout_ps;
    for (std::size_t i = 0; i < m_transfers.size(); ++i) {
        wait_ps(m_cfg.packet_processing_ps);
        const std::vector<std::uint8_t>& bytes = m_transfers[i].bytes;
        for (std::size_t k = 0; k < bytes.size(); ++k) {
            PcWrite w;
            w.transfer = i;
            w.byte = bytes[k];
            if (!wait_for_confirm(deadline_ps, timeout_ps, place_after(m_writes.size()))) return;
            w.t_confirm_ps = now_ps();
            if (k == 0 && i < m_waits.before_s.size()) {
                wait_ps(s_to_ps(m_waits.before_s[i]));
            }
            stall_if_due();
            w.t_write_ps = now_ps();
            wait_ps(m_cfg.write_latency_ps);
            m_port.usb_write(&w.byte, 1);
            m_writes.push_back(w);
            const bool last_of_transfer = k + 1 == bytes.size();
            timeout_ps =
                m_timeouts.round_trip_ps + kConfirmMarginPs +
                (last_of_transfer && i < m_timeouts.motion_after_ps.size() ? m_timeouts.motion_after_ps[i] : 0);
            deadline_ps = w.t_write_ps + timeout_ps;
        }
    }
    wait_ps(s_to_ps(m_waits.after_last_s));
    m_finished = true;
    m_t_end = now_ps();
}

}  // namespace cnc::host
