#include "architectures/atmega/link_bytes.hpp"

#include <algorithm>

namespace cnc::sim {

void read_link_bytes(host::PcProgram& pc, uart::Cp2102& cp2102, TimePs decision_ps,
                     const std::function<void(std::size_t transfer, TimePs t_ps)>& byte_at) {
    const std::size_t sent = std::min(pc.writes().size(), cp2102.tx_log().size());
    for (std::size_t j = pc.writes().first(); j < sent; ++j) {
        byte_at(pc.writes()[j].transfer, cp2102.tx_log()[j].t_start_bit_ps + decision_ps);
    }
    pc.drop_writes_before(sent);
    cp2102.drop_tx_log_before(sent);
    cp2102.drop_rx_log_before(cp2102.rx_log().size());
}

}  // namespace cnc::sim
