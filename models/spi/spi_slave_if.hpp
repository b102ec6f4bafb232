// Transaction view of an SPI slave, used by SpiMaster when trace_wires is false: the master calls select()
// when SS falls and deselect() when it rises (both at the current simulation time), and the slave answers with
// the bytes it would have shifted out on MISO. A slave must give the same result as over the wires.
#pragma once
#include <cstdint>
#include <systemc>
#include <vector>

#include "common/units.hpp"

namespace cnc::spi {

class SpiSlaveIf : public virtual sc_core::sc_interface {
public:
    virtual void select(TimePs t_ss_fall_ps) = 0;
    // `mosi`: the bytes shifted in while SS was low; `miso` receives as many bytes.
    virtual void deselect(TimePs t_ss_rise_ps, const std::vector<std::uint8_t>& mosi,
                          std::vector<std::uint8_t>& miso) = 0;
};

}  // namespace cnc::spi
