#include "fpga/spi/laser_latch.hpp"

namespace cnc::fpga {

LaserLatch::LaserLatch(const sc_core::sc_module_name& name) : sc_module(name), laser("laser"), fifo("fifo") {
    SC_HAS_PROCESS(LaserLatch);
    laser.initialize(false);  // reset: laser off
    SC_METHOD(on_applied);
    sensitive << m_applied;
    dont_initialize();
}

void LaserLatch::on_applied() {
    ++m_activations;
    // Runs one delta after the read that applied the frame, at that edge's time; one frame is applied per edge.
    laser.write(fifo->last_applied().laser_on);
}

}  // namespace cnc::fpga
