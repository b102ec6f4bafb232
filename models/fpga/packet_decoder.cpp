#include "fpga/packet_decoder.hpp"

namespace cnc::fpga {

namespace {

// The ramp's registers at reset, which the decoder's init packet (longer with a ramp) overwrites.
std::optional<RampDefaults> ramp_defaults(const FpgaConfig& cfg) {
    if (cfg.ramp == StepRamp::None) return std::nullopt;
    RampDefaults d{cfg.ramp_accel_default, cfg.ramp_start_default, std::nullopt};
    if (cfg.ramp == StepRamp::SCurve) d.jerk = cfg.ramp_jerk_default;
    return d;
}

}  // namespace

void MotionOutputs::put(TimedWriter& writer, const ClockGrid& clock, std::int64_t edge, const MotionFields& f) const {
    // The ports, not this (a temporary), are what the writes reach when they are due.
    writer.at(clock.at(edge),
              [&m = motion, &x = steps_x, &y = steps_y, &feed = feed_rate, &high = laser_high, &valid = pkt_valid, f] {
                  m.write(f.motion);
                  x.write(f.steps_x);
                  y.write(f.steps_y);
                  feed.write(f.feed);
                  high.write(f.laser_high);
                  valid.write(true);
              });
    writer.at(clock.at(edge + 1), [&valid = pkt_valid] { valid.write(false); });
}

PacketDecoder::PacketDecoder(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      rx_data("rx_data"),
      rx_valid("rx_valid"),
      motion("motion"),
      seq("seq"),
      steps_x("steps_x"),
      steps_y("steps_y"),
      feed_rate("feed_rate"),
      laser_high("laser_high"),
      pkt_valid("pkt_valid"),
      numerator_x("numerator_x"),
      numerator_y("numerator_y"),
      ramp_accel("ramp_accel"),
      ramp_start("ramp_start"),
      ramp_jerk("ramp_jerk"),
      cfg_valid("cfg_valid"),
      crc_error("crc_error"),
      repeat("repeat"),
      m_cfg(cfg),
      m_clock(clock_grid(cfg)),
      m_core(cfg.numerator_default, cfg.packet_crc, cfg.queue_depth == 0, ramp_defaults(cfg),
             cfg.laser_pwm_period_cycles > 0),
      m_writer("writer") {
    SC_HAS_PROCESS(PacketDecoder);
    numerator_x.initialize(cfg.numerator_default);  // seed 000 §5.2.3 (Π.4) reset value
    numerator_y.initialize(cfg.numerator_default);
    ramp_accel.initialize(cfg.ramp_accel_default);
    ramp_start.initialize(cfg.ramp_start_default);
    ramp_jerk.initialize(cfg.ramp_jerk_default);
    SC_METHOD(on_rx_valid);
    sensitive << rx_valid;
    dont_initialize();
    SC_METHOD(on_watchdog);
    sensitive << m_watchdog;
    dont_initialize();
}

void PacketDecoder::on_rx_valid() {
    ++m_activations;
    if (!rx_valid.read()) return;
    // rx_valid rose at edge n; the decoder's always block sees it (and rx_data) at edge n+1. A watchdog
    // that expired at or before edge n has already run (timed event, delta 0 of its edge).
    const std::int64_t edge = m_clock.first_after(now_ps());
    const TimePs t = m_clock.at(edge);
    const auto done = m_core.on_byte(rx_data.read());
    if (done == PacketDecoderCore::Completed::Motion) {
        const MotionFields f = m_core.motion();
        m_motions.push_back({t, f});
        m_writer.at(t, [this, f] { seq.write(f.seq); });
        MotionOutputs{motion, steps_x, steps_y, feed_rate, laser_high, pkt_valid}.put(m_writer, m_clock, edge, f);
    } else if (done == PacketDecoderCore::Completed::Init) {
        const InitFields f = m_core.init();
        m_writer.at(t, [this, f] {
            numerator_x.write(f.num_x);
            numerator_y.write(f.num_y);
            if (m_cfg.ramp != StepRamp::None) {
                ramp_accel.write(f.ramp_accel);
                ramp_start.write(f.ramp_start);
                ramp_jerk.write(f.ramp_jerk);
            }
            cfg_valid.write(true);
        });
        m_writer.at(m_clock.at(edge + 1), [this] { cfg_valid.write(false); });
    } else if (done == PacketDecoderCore::Completed::BadCrc) {
        ++m_crc_errors;
        strobe(crc_error, edge);
    } else if (done == PacketDecoderCore::Completed::Repeat) {
        ++m_repeats;
        strobe(repeat, edge);
    }
    // timeout_cnt restarts at this byte: with no byte on edges edge+1 .. edge+TIMEOUT_CYCLES, the edge
    // edge+TIMEOUT_CYCLES sees timeout_cnt == TIMEOUT_CYCLES-1 and clears the partial packet.
    m_watchdog.cancel();
    if (m_core.timeout_active()) {
        m_watchdog.notify(ps(m_clock.at(edge + std::int64_t{m_cfg.watchdog_cycles}) - now_ps()));
    }
}

void PacketDecoder::strobe(sc_core::sc_out<bool>& port, std::int64_t edge) {
    m_writer.at(m_clock.at(edge), [&port] { port.write(true); });
    m_writer.at(m_clock.at(edge + 1), [&port] { port.write(false); });
}

void PacketDecoder::on_watchdog() {
    ++m_activations;
    m_core.on_timeout();
    ++m_watchdog_resets;
}

}  // namespace cnc::fpga
