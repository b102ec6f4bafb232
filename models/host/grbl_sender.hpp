// A G-code sender for grbl's line protocol (host/core/grbl/grbl_stream.hpp) on the CP2102: it listens from the
// start (the MCU's reset, and so its start-up message, comes as the port opens), writes each line the stream lets
// it after its own work (host.packet_processing_us) and the OS write latency (host.write_latency_us), asks for a
// status report ('?') every status interval, and reads grbl's answers line by line as USB delivers them.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "common/units.hpp"
#include "host/core/grbl/grbl_stream.hpp"
#include "host/core/sender_config.hpp"
#include "uart/cp2102.hpp"

namespace cnc::host {

struct GrblSenderConfig {
    TimePs processing_ps = 200 * kPsPerUs;  // the sender's work per line (host.packet_processing_us)
    TimePs write_latency_ps = 100 * kPsPerUs;
    // Status queries while the job streams; 0: none until the last line is answered. Universal G-code Sender asks
    // every 200 ms by default.
    TimePs status_interval_ps = 200 * kPsPerMs;
    // The start-up message must come within this, else the link or the firmware is not working.
    TimePs banner_timeout_ps = 2 * kPsPerSec;
    StallWindow stall;  // a fault: none by default
};

// A line as it crossed the port: written by the sender, or read from grbl.
struct GrblLineRecord {
    TimePs t_ps = 0;
    bool written = false;
    std::string text;  // without its line end; "?" for a status query
};

class GrblSender : public sc_core::sc_module {
public:
    GrblSender(const sc_core::sc_module_name& name, const GrblSenderConfig& cfg, uart::Cp2102& port,
               grbl::Stream stream);

    [[nodiscard]] const grbl::Stream& stream() const { return m_stream; }
    [[nodiscard]] bool finished() const { return m_finished; }
    [[nodiscard]] TimePs t_end_ps() const { return m_t_end_ps; }  // Idle seen (-1: not yet)
    [[nodiscard]] const std::optional<std::string>& failure() const { return m_failure; }
    // How long the host stall (GrblSenderConfig::stall) held the sender up.
    [[nodiscard]] TimePs stalled_ps() const { return m_stall.held_ps(); }
    [[nodiscard]] const std::vector<GrblLineRecord>& lines() const { return m_lines; }

private:
    void run();
    void read_port();

    const GrblSenderConfig m_cfg;
    uart::Cp2102& m_port;
    grbl::Stream m_stream;
    std::string m_partial;  // received bytes of a line not yet ended
    std::vector<GrblLineRecord> m_lines;
    bool m_finished = false;
    TimePs m_t_end_ps = -1;
    std::optional<std::string> m_failure;
    HostStall m_stall;
};

}  // namespace cnc::host
