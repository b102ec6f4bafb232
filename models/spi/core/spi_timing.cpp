#include "spi/core/spi_timing.hpp"

#include <sstream>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::spi {

namespace {
void require(bool ok, const char* key, const std::string& what) {
    if (!ok) throw BadInput(std::string("spi: ") + key, what);
}
}  // namespace

void validate(const SpiConfig& cfg) {
    // cycles_to_ps counts half periods at 2 x sclk_hz; 100 MHz is beyond any Pi-class master anyway.
    require(cfg.sclk_hz >= 1 && cfg.sclk_hz <= 100'000'000, "sclk_hz", "must be in 1..100000000 Hz");
    require(cfg.cs_setup_ps > 0, "cs_setup_ps", "must be > 0 (mode 0: MISO bit 0 must be out before SCLK rises)");
    require(cfg.cs_hold_ps >= 0, "cs_hold_ps", "must be >= 0");
    require(cfg.ss_idle_min_ps > 0, "ss_idle_min_ps", "must be > 0 (the slave must see SS high between frames)");
}

TimePs transfer_time_ps(const SpiConfig& cfg, std::size_t bits) {
    return cfg.cs_setup_ps + cycles_to_ps(static_cast<std::int64_t>(bits), cfg.sclk_hz) + cfg.cs_hold_ps;
}

TimePs transfer_slot_ps(const SpiConfig& cfg, std::size_t bits) {
    return transfer_time_ps(cfg, bits) + cfg.ss_idle_min_ps;
}

TimePs sclk_rise_ps(const SpiConfig& cfg, std::int64_t bit) {
    return cfg.cs_setup_ps + cycles_to_ps(2 * bit, 2 * std::int64_t{cfg.sclk_hz});
}

TimePs sclk_fall_ps(const SpiConfig& cfg, std::int64_t bit) {
    return cfg.cs_setup_ps + cycles_to_ps(2 * bit + 1, 2 * std::int64_t{cfg.sclk_hz});
}

TimePs sclk_half_period_ps(const SpiConfig& cfg) {
    return cycles_to_ps(1, 2 * std::int64_t{cfg.sclk_hz});
}

void check_transfer_fits(const SpiConfig& cfg, std::size_t bits, TimePs servo_period_ps) {
    const TimePs slot = transfer_slot_ps(cfg, bits);
    if (slot <= servo_period_ps) return;
    std::ostringstream s;
    s << "a " << bits << "-bit frame at " << cfg.sclk_hz << " Hz takes " << ps_to_us(transfer_time_ps(cfg, bits))
      << " us with SS low (cs_setup " << ps_to_us(cfg.cs_setup_ps) << " us + " << bits << " bits + cs_hold "
      << ps_to_us(cfg.cs_hold_ps) << " us) and " << ps_to_us(slot) << " us with the SS-high gap, more than the "
      << ps_to_us(servo_period_ps) << " us servo period; raise the SCLK rate or the servo period";
    throw BadInput("spi: sclk_hz", s.str());
}

}  // namespace cnc::spi
