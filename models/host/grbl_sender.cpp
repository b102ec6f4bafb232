#include "host/grbl_sender.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "common/sc_time.hpp"

namespace cnc::host {

namespace {

// A status query while the job drains, when none is asked for during it: Universal G-code Sender's default rate.
constexpr TimePs kDrainStatusPs = 200 * kPsPerMs;

}  // namespace

GrblSender::GrblSender(const sc_core::sc_module_name& name, const GrblSenderConfig& cfg, uart::Cp2102& port,
                       grbl::Stream stream)
    : sc_module(name), m_cfg(cfg), m_port(port), m_stream(std::move(stream)), m_stall(cfg.stall) {
    SC_HAS_PROCESS(GrblSender);
    SC_THREAD(run);
}

void GrblSender::read_port() {
    while (const std::optional<std::uint8_t> b = m_port.read_byte()) {
        if (*b == '\n') {
            m_lines.push_back({now_ps(), false, m_partial});
            m_stream.received(m_partial);
            m_partial.clear();
        } else if (*b >= 0x20 && *b < 0x7F) {
            m_partial.push_back(static_cast<char>(*b));
        } else if (*b != '\r') {
            // grbl answers in printable ASCII; anything else is a byte the line changed, kept readable in the
            // report (which is UTF-8 JSON).
            m_partial += fmt::format(FMT_STRING("\\x{:02X}"), *b);
        }
    }
}

void GrblSender::run() {
    const TimePs banner_deadline_ps = now_ps() + m_cfg.banner_timeout_ps;
    const TimePs status_ps = m_cfg.status_interval_ps;
    TimePs next_status_ps = status_ps > 0 ? status_ps : -1;
    for (;;) {
        if (const TimePs wait = m_stall.wait_at(now_ps())) wait_ps(wait);
        read_port();
        const grbl::Phase phase = m_stream.phase();
        if (phase == grbl::Phase::Failed) {
            m_failure = m_stream.failure();
            return;
        }
        if (phase == grbl::Phase::Done) {
            m_finished = true;
            m_t_end_ps = now_ps();
            return;
        }
        if (phase == grbl::Phase::Banner && now_ps() >= banner_deadline_ps) {
            m_failure = fmt::format(FMT_STRING("no grbl start-up message (\"Grbl ...\") within {:.1f} s; received "
                                               "\"{}\""),
                                    ps_to_s(m_cfg.banner_timeout_ps), m_partial);
            return;
        }
        if (m_stream.draining() && next_status_ps < 0) next_status_ps = now_ps();
        if (phase != grbl::Phase::Banner && next_status_ps >= 0 && now_ps() >= next_status_ps) {
            m_port.usb_write({'?'});
            m_lines.push_back({now_ps(), true, "?"});
            next_status_ps = now_ps() + (status_ps > 0 ? status_ps : kDrainStatusPs);
        }
        if (std::optional<std::string> line = m_stream.next_write()) {
            wait_ps(m_cfg.processing_ps + m_cfg.write_latency_ps);
            m_port.usb_write(std::vector<std::uint8_t>(line->begin(), line->end()));
            line->pop_back();
            m_lines.push_back({now_ps(), true, std::move(*line)});
            continue;
        }
        TimePs wake_ps = phase == grbl::Phase::Banner ? banner_deadline_ps : -1;
        if (next_status_ps >= 0) wake_ps = wake_ps < 0 ? next_status_ps : std::min(wake_ps, next_status_ps);
        if (wake_ps < 0) {
            sc_core::wait(m_port.data_event());
        } else {
            sc_core::wait(ps_time(std::max<TimePs>(0, wake_ps - now_ps())), m_port.data_event());
        }
    }
}

}  // namespace cnc::host
