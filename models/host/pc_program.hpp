// The seed 003 PC program (CAD2G V42, §3.3-3.4, §5.3.2-5.4) as the host side of the atmega architecture: it opens
// the port (PurgeComm, then Sleep(ARDUINO_WAIT_TIME) = host.settle_s), computes each command or chord
// (host.packet_processing_us) and writes its bytes ONE PER WriteFile call (writeSerialPort always writes 1 byte),
// each after it has read a confirm byte from the MCU (non-blocking readSerialPort polled until a byte is there).
// The seed's program has no timeout: without a confirm it waits forever (the run then ends at
// scenario.max_sim_s). Any received byte counts as a confirm, as readSerialPort only reports that bytes came;
// values other than 0x06 are counted.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

#include "common/units.hpp"
#include "host/core/host_waits.hpp"
#include "host/core/seed003/plan.hpp"
#include "host/sender.hpp"
#include "uart/cp2102.hpp"

namespace cnc::host {

struct PcWrite {
    std::size_t transfer = 0;  // index into the transfers
    std::uint8_t byte = 0;
    std::uint8_t confirm = 0;  // the byte read before it
    TimePs t_confirm_ps = 0;   // the program read the confirm
    TimePs t_write_ps = 0;     // WriteFile called (the byte reaches the CP2102 after host.write_latency_us)
};

class PcProgram : public sc_core::sc_module {
public:
    // Uses the timing fields of SenderConfig: settle_ps, packet_processing_ps, write_latency_ps.
    PcProgram(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
              std::vector<seed003::Transfer> transfers);

    // Host waits of the job (G4 dwells, M0 pauses, Z moves), one per transfer: slept after the confirm that
    // asks for its first byte (the firmware sends it once the previous motion has ended) and before the write.
    void set_waits(const UnitWaits& waits);

    [[nodiscard]] const std::vector<seed003::Transfer>& transfers() const { return m_transfers; }
    [[nodiscard]] const std::vector<PcWrite>& writes() const { return m_writes; }
    [[nodiscard]] std::int64_t unexpected_confirms() const { return m_unexpected; }
    [[nodiscard]] bool finished() const { return m_finished; }
    [[nodiscard]] TimePs t_end_ps() const { return m_t_end; }  // the last byte was written (-1: not yet)

private:
    void run();
    std::uint8_t wait_for_confirm();

    const SenderConfig m_cfg;
    uart::Cp2102& m_port;
    const std::vector<seed003::Transfer> m_transfers;
    UnitWaits m_waits;
    std::vector<PcWrite> m_writes;
    std::int64_t m_unexpected = 0;
    bool m_finished = false;
    TimePs m_t_end = -1;
};

}  // namespace cnc::host
