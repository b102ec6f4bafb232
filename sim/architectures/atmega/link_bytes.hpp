// The bytes the PC program wrote, as the MCU received them: the program's writes and the CP2102's TX log hold a
// record per byte (byte j of one is byte j of the other), which a long job cannot keep. Each call hands over the
// bytes the CP2102 has sent since the last one and drops them from both logs, with the CP2102's RX log (the
// confirms: only their count is reported), so that the logs hold one call's bytes at most.
#pragma once
#include <cstddef>
#include <functional>

#include "common/units.hpp"
#include "host/pc_program.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

// `byte_at(transfer, t_ps)`: a byte of that transfer had its stop bit's middle at the MCU's bit clock at t_ps (the
// start bit plus `decision_ps`, uart::decision_offset_ps of the MCU's receiver), in the order written.
void read_link_bytes(host::PcProgram& pc, uart::Cp2102& cp2102, TimePs decision_ps,
                     const std::function<void(std::size_t transfer, TimePs t_ps)>& byte_at);

}  // namespace cnc::sim
