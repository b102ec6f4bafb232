// A sender's side of grbl's line protocol, as grbl's stream.py and Universal G-code Sender speak it:
//  - after the start-up message ("Grbl ..."), the settings one at a time, each answered before the next (grbl
//    writes them to EEPROM, with the steppers idle);
//  - then the job: with character counting, a line is written while the bytes in flight (sent, not yet answered
//    by "ok" or "error:N") and the line's own, newline included, fit in grbl's receive buffer (RX_BUFFER_SIZE 128,
//    a ring that holds 127); with send-response, a line after the answer of the one before;
//  - an "error:N" names the line it answers (the oldest in flight): strict, the sender writes nothing more;
//    lenient, it is reported and the job goes on, as senders do. "ALARM:N" stops the job;
//  - the job has ended when every line has been answered and a status report ("?") says Idle.
// Status reports are asked for with '?', a real-time byte that grbl takes out of the stream: it is not counted.
#pragma once
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "host/core/grbl/grbl_lines.hpp"

namespace cnc::host::grbl {

enum class Protocol { CharacterCounting, SendResponse };

struct StreamConfig {
    Protocol protocol = Protocol::CharacterCounting;
    std::size_t rx_buffer_bytes = 128;  // grbl's RX_BUFFER_SIZE on the 328P
    bool strict = true;                 // scenario.gcode_policy
};

struct LineError {
    SendLine line;
    std::string answer;  // "error:20"
};

enum class Phase { Banner, Settings, Job, Draining, Done, Failed };

class Stream {
public:
    Stream(StreamConfig cfg, std::vector<SendLine> settings, std::vector<SendLine> job);

    // One line received from grbl, without its line end.
    void received(const std::string& line);
    // The next line to write now, newline included; none while the window is full or nothing is to be sent.
    [[nodiscard]] std::optional<std::string> next_write();
    // After the job's last answer: a status report is wanted to see Idle.
    [[nodiscard]] bool draining() const { return m_phase == Phase::Draining; }

    [[nodiscard]] Phase phase() const { return m_phase; }
    [[nodiscard]] const std::vector<SendLine>& job() const { return m_job; }
    [[nodiscard]] const std::string& failure() const { return m_failure; }
    [[nodiscard]] const std::vector<LineError>& errors() const { return m_errors; }
    // The setting grbl refused, when that stopped the stream.
    [[nodiscard]] const std::optional<LineError>& refused_setting() const { return m_refused_setting; }
    [[nodiscard]] std::size_t in_flight_bytes() const { return m_in_flight_bytes; }
    [[nodiscard]] std::size_t most_in_flight_bytes() const { return m_most_in_flight_bytes; }
    [[nodiscard]] std::size_t job_lines_sent() const { return m_next_job; }
    [[nodiscard]] std::size_t job_lines_answered() const { return m_answered_job; }
    [[nodiscard]] const std::string& banner() const { return m_banner; }
    [[nodiscard]] const std::string& last_status() const { return m_last_status; }

private:
    void answered(const std::string& answer);
    // Settings -> Job -> Draining, each once all its lines are sent and answered.
    void advance_phase();
    void fail(std::string why);

    StreamConfig m_cfg;
    std::vector<SendLine> m_settings;
    std::vector<SendLine> m_job;
    Phase m_phase = Phase::Banner;
    std::size_t m_next_setting = 0;
    std::size_t m_next_job = 0;
    std::size_t m_answered_job = 0;
    struct InFlight {
        const SendLine* line;
        std::size_t bytes;
        bool setting;
    };
    std::deque<InFlight> m_in_flight;
    std::size_t m_in_flight_bytes = 0;
    std::size_t m_most_in_flight_bytes = 0;
    std::vector<LineError> m_errors;
    std::optional<LineError> m_refused_setting;
    std::string m_failure;
    std::string m_banner;
    std::string m_last_status;
};

}  // namespace cnc::host::grbl
