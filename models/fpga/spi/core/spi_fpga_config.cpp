#include "fpga/spi/core/spi_fpga_config.hpp"

#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::fpga {

namespace {
void require(bool ok, const std::string& key, const std::string& what) {
    if (!ok) throw BadInput(key, what);
}
// Latest time after a pin change at which the logic's registered outputs can react to it.
TimePs reaction_ps(const SpiFpgaConfig& cfg) {
    return (kSpiSyncStages + 1) * clock_period_ps(cfg);
}
}  // namespace

TimePs clock_period_ps(const SpiFpgaConfig& cfg) {
    return kPsPerSec / static_cast<TimePs>(cfg.clk_hz);
}

ClockGrid clock_grid(const SpiFpgaConfig& cfg) {
    return ClockGrid(cfg.clk_hz, cfg.clock, "fpga: clock");
}

void validate(const SpiFpgaConfig& cfg) {
    require(cfg.clk_hz > 0 && kPsPerSec % cfg.clk_hz == 0, "fpga: clk_hz",
            "must divide 1e12 so that a clock period is a whole number of ps");
    require(cfg.fifo_depth >= 1, "fpga: fifo_depth", "must be >= 1");
    require(cfg.pulse_cycles >= 1 && cfg.pulse_cycles < spi::kMaxPeriodCycles, "fpga: pulse_cycles",
            "must be in 1..2^30-2 (the rate word's period field is 30 bits)");
    require(cfg.dir_setup_cycles >= 1, "fpga: dir_setup_cycles", "must be >= 1");
    require(cfg.dir_hold_cycles >= 1, "fpga: dir_hold_cycles", "must be >= 1");
}

std::uint32_t max_sclk_hz(const SpiFpgaConfig& cfg) {
    // The half period is floor(1e12 / 2f) ps; it exceeds the limit L exactly when f <= 1e12 / (2 (L + 1)).
    return static_cast<std::uint32_t>(kPsPerSec / (2 * (reaction_ps(cfg) + 1)));
}

void check_link(const spi::SpiConfig& link, const SpiFpgaConfig& cfg) {
    const TimePs limit = reaction_ps(cfg);
    if (spi::sclk_half_period_ps(link) <= limit) {
        std::ostringstream s;
        s << "SCLK " << link.sclk_hz << " Hz is too fast for the FPGA's oversampling SPI slave at " << cfg.clk_hz
          << " Hz: MISO changes up to " << kSpiSyncStages + 1 << " clocks (" << ps_to_ns(limit)
          << " ns) after a falling SCLK edge and must be stable before the next rising edge, half an SCLK period ("
          << ps_to_ns(spi::sclk_half_period_ps(link)) << " ns) later; the highest usable rate is " << max_sclk_hz(cfg)
          << " Hz";
        throw BadInput("spi: sclk_hz", s.str());
    }
    if (link.cs_setup_ps <= limit) {
        std::ostringstream s;
        s << "cs_setup " << link.cs_setup_ps << " ps is too short: the FPGA needs more than " << limit
          << " ps after SS falls to put the first reply bit on MISO";
        throw BadInput("spi: cs_setup_ps", s.str());
    }
    if (link.ss_idle_min_ps < clock_period_ps(cfg)) {
        std::ostringstream s;
        s << "ss_idle_min " << link.ss_idle_min_ps << " ps is shorter than one FPGA clock (" << clock_period_ps(cfg)
          << " ps): the slave could miss the end of a frame";
        throw BadInput("spi: ss_idle_min_ps", s.str());
    }
}

}  // namespace cnc::fpga
