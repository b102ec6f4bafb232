#include "fpga/spi/core/spi_slave_core.hpp"

#include "fpga/spi/core/spi_fpga_config.hpp"

namespace cnc::fpga {

void SpiSlaveCore::sample(std::int64_t edge, bool ss, bool sclk, bool mosi, std::vector<SlaveEvent>& out) {
    const std::int64_t act = edge + kSpiSyncStages;
    if (m_ss && !ss) out.push_back(select(edge));
    // SCLK edges count only while the synchronised SS is low at the same sample (as `cs & clk_rise` in RTL).
    if (!ss && sclk != m_sclk) {
        if (sclk) {
            if (m_bits % 8 == 0) m_bytes.push_back(0);
            if (mosi) m_bytes.back() = static_cast<std::uint8_t>(m_bytes.back() | (0x80U >> (m_bits % 8)));
            ++m_bits;
        } else {
            SlaveEvent e;
            e.kind = SlaveEvent::Kind::MisoShift;
            e.edge = act;
            e.miso_bit = ++m_falls;
            out.push_back(e);
        }
    }
    if (!m_ss && ss) {
        SlaveEvent e;
        e.kind = SlaveEvent::Kind::FrameEnd;
        e.edge = act;
        e.mosi_bits = m_bits;
        e.mosi = m_bytes;
        if (m_bits % 8 != 0) e.mosi.pop_back();
        out.push_back(e);
    }
    m_ss = ss;
    m_sclk = sclk;
}

SlaveEvent SpiSlaveCore::select(std::int64_t edge) {
    m_bytes.clear();
    m_bits = 0;
    m_falls = 0;
    SlaveEvent e;
    e.kind = SlaveEvent::Kind::FrameStart;
    e.edge = edge + kSpiSyncStages;
    return e;
}

SlaveEvent SpiSlaveCore::deselect(std::int64_t edge, const std::vector<std::uint8_t>& mosi) {
    SlaveEvent e;
    e.kind = SlaveEvent::Kind::FrameEnd;
    e.edge = edge + kSpiSyncStages;
    e.mosi = mosi;
    e.mosi_bits = 8 * mosi.size();
    return e;
}

}  // namespace cnc::fpga
