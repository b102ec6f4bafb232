// packet_decoder (seed 000 §5.2.3, Π.4): bytes from uart_rx -> registered motion/init fields with a one-clock
// pkt_valid/cfg_valid, and the 100 ms inter-byte watchdog as one timed event instead of a counter.
#pragma once
#include <cstddef>
#include <cstdint>
#include <systemc>

#include "common/record_log.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/packet_decoder_core.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

// The ports a motion packet's fields are registered on, with a one-clock pkt_valid: packet_decoder's own, and the
// packet queue's to step_gen (packet_queue.hpp).
struct MotionOutputs {
    sc_core::sc_out<std::uint8_t>& motion;
    sc_core::sc_out<std::int32_t>& steps_x;
    sc_core::sc_out<std::int32_t>& steps_y;
    sc_core::sc_out<std::uint16_t>& feed_rate;
    sc_core::sc_out<std::uint16_t>& laser_high;
    sc_core::sc_out<bool>& pkt_valid;

    // `f` on the ports at edge `edge`, pkt_valid high for that clock.
    void put(TimedWriter& writer, const ClockGrid& clock, std::int64_t edge, const MotionFields& f) const;
};

class PacketDecoder : public sc_core::sc_module {
public:
    sc_core::sc_in<std::uint8_t> rx_data;
    sc_core::sc_in<bool> rx_valid;
    sc_core::sc_out<std::uint8_t> motion;
    sc_core::sc_out<std::uint8_t> seq;  // b0[6:2], read by the packet queue
    sc_core::sc_out<std::int32_t> steps_x;
    sc_core::sc_out<std::int32_t> steps_y;
    sc_core::sc_out<std::uint16_t> feed_rate;
    sc_core::sc_out<std::uint16_t> laser_high;  // with fpga.laser_pwm (0 without)
    sc_core::sc_out<bool> pkt_valid;
    sc_core::sc_out<std::uint32_t> numerator_x;
    sc_core::sc_out<std::uint32_t> numerator_y;
    sc_core::sc_out<std::uint32_t> ramp_accel;  // with fpga.ramp: the init packet's ramp registers
    sc_core::sc_out<std::uint32_t> ramp_start;
    sc_core::sc_out<std::uint32_t> ramp_jerk;  // with the S-curve
    sc_core::sc_out<bool> cfg_valid;
    // With the packet check: one-clock strobes at a packet's last byte, as pkt_valid.
    sc_core::sc_out<bool> crc_error;
    sc_core::sc_out<bool> repeat;

    PacketDecoder(const sc_core::sc_module_name& name, const FpgaConfig& cfg);

    struct MotionOut {
        TimePs t_pkt_valid_ps;
        MotionFields fields;
    };
    // Every completed motion packet, in order (one per pkt_valid pulse).
    [[nodiscard]] const RecordLog<MotionOut>& motions() const { return m_motions; }
    // The packets before index `end` have been read: they go.
    void drop_motions_before(std::size_t end) { m_motions.drop_before(end); }
    [[nodiscard]] std::uint64_t watchdog_resets() const { return m_watchdog_resets; }
    [[nodiscard]] std::uint64_t crc_errors() const { return m_crc_errors; }
    [[nodiscard]] std::uint64_t repeats() const { return m_repeats; }
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void on_rx_valid();
    void on_watchdog();
    // A one-clock strobe on `port` at edge `edge`.
    void strobe(sc_core::sc_out<bool>& port, std::int64_t edge);

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    PacketDecoderCore m_core;
    sc_core::sc_event m_watchdog;
    TimedWriter m_writer;
    RecordLog<MotionOut> m_motions;
    std::uint64_t m_watchdog_resets = 0;
    std::uint64_t m_crc_errors = 0;
    std::uint64_t m_repeats = 0;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
