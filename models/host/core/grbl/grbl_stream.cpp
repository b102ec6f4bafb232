#include "host/core/grbl/grbl_stream.hpp"

#include <algorithm>
#include <utility>

namespace cnc::host::grbl {

namespace {

bool starts_with(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

}  // namespace

Stream::Stream(StreamConfig cfg, std::vector<SendLine> settings, std::vector<SendLine> job)
    : m_cfg(cfg), m_settings(std::move(settings)), m_job(std::move(job)) {}

void Stream::fail(std::string why) {
    m_phase = Phase::Failed;
    m_failure = std::move(why);
}

void Stream::received(const std::string& line) {
    if (m_phase == Phase::Done || m_phase == Phase::Failed) return;
    if (starts_with(line, "Grbl ")) {
        if (m_phase != Phase::Banner) {
            fail("grbl restarted (\"" + line + "\") with " + std::to_string(m_in_flight.size()) + " lines in flight");
            return;
        }
        m_banner = line;
        m_phase = Phase::Settings;
        advance_phase();
        return;
    }
    // Before its start-up message grbl may report on itself (error:7, its settings read from a blank EEPROM and
    // restored to its defaults): no line of ours is in flight yet.
    if (m_phase == Phase::Banner) return;
    if (starts_with(line, "<")) {
        m_last_status = line;
        if (m_phase == Phase::Draining && starts_with(line, "<Idle")) m_phase = Phase::Done;
        return;
    }
    if (line == "ok" || starts_with(line, "error:")) {
        answered(line);
        return;
    }
    if (starts_with(line, "ALARM:")) {
        const std::string where = m_in_flight.empty() ? std::string() : " at " + m_in_flight.front().line->where;
        fail("grbl raised " + line + where);
    }
    // Anything else ("[MSG:...]", the lines of "$$") is information.
}

void Stream::answered(const std::string& answer) {
    if (m_in_flight.empty()) {
        fail("grbl answered \"" + answer + "\" with no line in flight");
        return;
    }
    const InFlight f = m_in_flight.front();
    m_in_flight.pop_front();
    m_in_flight_bytes -= f.bytes;
    if (!f.setting) ++m_answered_job;
    if (answer != "ok") {
        m_errors.push_back({*f.line, answer});
        if (f.setting) {
            m_refused_setting = m_errors.back();
            fail("grbl answered " + answer + " to the setting " + f.line->text + " (" + f.line->where + ")");
            return;
        }
        if (m_cfg.strict) {
            fail("grbl answered " + answer + " to " + f.line->where + ": " + f.line->text);
            return;
        }
    }
    advance_phase();
}

void Stream::advance_phase() {
    if (!m_in_flight.empty()) return;
    if (m_phase == Phase::Settings && m_next_setting == m_settings.size()) m_phase = Phase::Job;
    if (m_phase == Phase::Job && m_next_job == m_job.size()) m_phase = Phase::Draining;
}

std::optional<std::string> Stream::next_write() {
    const SendLine* line = nullptr;
    bool setting = false;
    if (m_phase == Phase::Settings) {
        if (!m_in_flight.empty() || m_next_setting == m_settings.size()) return std::nullopt;
        line = &m_settings[m_next_setting++];
        setting = true;
    } else if (m_phase == Phase::Job) {
        if (m_next_job == m_job.size()) return std::nullopt;
        const std::size_t bytes = m_job[m_next_job].text.size() + 1;
        const bool fits = m_cfg.protocol == Protocol::CharacterCounting
                              ? m_in_flight_bytes + bytes <= m_cfg.rx_buffer_bytes - 1
                              : m_in_flight.empty();
        // A line longer than the whole buffer goes alone, as stream.py lets it (grbl reads it as it arrives).
        if (!fits && !m_in_flight.empty()) return std::nullopt;
        line = &m_job[m_next_job++];
    } else {
        return std::nullopt;
    }
    const std::size_t bytes = line->text.size() + 1;
    m_in_flight.push_back({line, bytes, setting});
    m_in_flight_bytes += bytes;
    m_most_in_flight_bytes = std::max(m_most_in_flight_bytes, m_in_flight_bytes);
    return line->text + "\n";
}

}  // namespace cnc::host::grbl
