// The seed 003 PC program (CAD2G V42, §3.3, §5.3.2-5.4) as the host side of the atmega architecture: it opens
// the port (PurgeComm, then Sleep(ARDUINO_WAIT_TIME) = host.settle_s), computes each command or chord
// (host.packet_processing_us) and writes its bytes ONE PER WriteFile call (writeSerialPort always writes 1 byte),
// each after it has read a confirm byte from the MCU (non-blocking readSerialPort polled until a byte is there).
//
// The seed's program has no timeout and takes any received byte as a confirm (readSerialPort only reports that
// bytes came), so a firmware that does not speak its protocol is fed the whole job (grbl's start-up message
// counts as confirms) or waited for forever (a silent MCU). This model checks what the seed does not, so that a
// run on a link that is not working ends at once with the reason instead of measuring a job that never ran:
//  - a byte other than the confirm 0x06 is a protocol mismatch: the program stops and names the bytes that came
//    (up to kShownBytes, as text and hex, read for as long as that many take to arrive);
//  - no confirm within the confirm timeout is a dead link or firmware: the program stops and says after which
//    byte. The timeout after a byte is its round trip (byte_round_trip_ps), plus, after the last byte of a
//    transfer, the motion the firmware runs before it asks for the next one (host/core/cad2g/firmware_busy.hpp),
//    plus kConfirmMarginPs; before the first byte (after the settle) the round trip and the margin.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "common/record_log.hpp"
#include "common/units.hpp"
#include "host/core/cad2g/plan.hpp"
#include "host/core/host_waits.hpp"
#include "host/sender.hpp"
#include "uart/cp2102.hpp"

namespace cnc::host {

// The seed firmware confirms the next byte within tens of cycles of reading one (a few us at 16 MHz); 100 ms is
// four orders of magnitude more, for a firmware that works longer per byte and for the cycles around each motion
// that firmware_busy.hpp does not count, and it still ends the run of a silent firmware well within a second
// (0.3 s settle + 0.1 s).
inline constexpr TimePs kConfirmMarginPs = 100 * kPsPerMs;

// Bytes of a mismatch shown in the message: grbl 1.1's start-up message is 28 bytes.
inline constexpr std::size_t kShownBytes = 32;

// One confirmed byte's trip: the PC's write latency, a USB frame out, the byte and its confirm on the line (8N1
// at the requested rate), a USB frame in and the driver's latency.
[[nodiscard]] TimePs byte_round_trip_ps(const SenderConfig& cfg, const uart::Cp2102Config& link);

struct ConfirmTimeouts {
    TimePs round_trip_ps = 0;             // byte_round_trip_ps()
    std::vector<TimePs> motion_after_ps;  // per transfer: cad2g::motion_before_next_confirm_s()
};

struct PcWrite {
    std::size_t transfer = 0;  // index into the transfers
    std::uint8_t byte = 0;
    TimePs t_confirm_ps = 0;  // the program read the confirm
    TimePs t_write_ps = 0;    // WriteFile called (the byte reaches the CP2102 after host.write_latency_us)
};

// Why the program stopped before the end of the job, and when.
struct LinkFailure {
    TimePs t_ps = 0;
    std::string reason;
};

class PcProgram : public sc_core::sc_module {
public:
    // Uses the timing fields of SenderConfig: settle_ps, packet_processing_ps, write_latency_ps.
    PcProgram(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
              std::vector<cad2g::Transfer> transfers, ConfirmTimeouts timeouts);

    // Host waits of the job (G4 dwells, M0 pauses, Z moves), one per transfer: slept after the confirm that
    // asks for its first byte (the firmware sends it once the previous motion has ended) and before the write.
    void set_waits(const UnitWaits& waits);

    [[nodiscard]] const std::vector<cad2g::Transfer>& transfers() const { return m_transfers; }
    // Every byte written, numbered over the whole run (size() counts the dropped ones too).
    [[nodiscard]] const RecordLog<PcWrite>& writes() const { return m_writes; }
    // The reader has read the writes before index `end`: they go.
    void drop_writes_before(std::size_t end) { m_writes.drop_before(end); }
    [[nodiscard]] bool finished() const { return m_finished; }
    [[nodiscard]] TimePs t_end_ps() const { return m_t_end; }  // the last byte was written (-1: not yet)
    [[nodiscard]] const std::optional<LinkFailure>& failure() const { return m_failure; }
    // How long the host stall (SenderConfig::stall) held the program up.
    [[nodiscard]] TimePs stalled_ps() const { return m_stall.held_ps(); }

private:
    void run();
    // True when the confirm came before `deadline_ps`; otherwise records the failure. `place` says where in the
    // job the program is ("before the job's first byte").
    bool wait_for_confirm(TimePs deadline_ps, TimePs timeout_ps, const std::string& place);
    void stop_on_mismatch(std::uint8_t first, const std::string& place);
    // Inside the stall: waits for its end.
    void stall_if_due();
    [[nodiscard]] std::string place_after(std::size_t written) const;

    const SenderConfig m_cfg;
    uart::Cp2102& m_port;
    const std::vector<cad2g::Transfer> m_transfers;
    const ConfirmTimeouts m_timeouts;
    std::size_t m_job_bytes = 0;
    UnitWaits m_waits;
    RecordLog<PcWrite> m_writes;
    bool m_finished = false;
    TimePs m_t_end = -1;
    std::optional<LinkFailure> m_failure;
    HostStall m_stall;
};

}  // namespace cnc::host
