#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/fpga_uart/dead_time.hpp"
#include "architectures/fpga_uart/fpga_uart.hpp"
#include "architectures/fpga_uart/fpga_uart_settings.hpp"
#include "architectures/fpga_uart/init_registers.hpp"
#include "architectures/fpga_uart/job_segments.hpp"
#include "architectures/fpga_uart/packet_faults.hpp"
#include "architectures/fpga_uart/ramp_commanded.hpp"
#include "architectures/serial_host/host_faults.hpp"
#include "architectures/serial_host/link_checks.hpp"
#include "common/bad_input.hpp"
#include "common/record_log.hpp"
#include "common/sc_time.hpp"
#include "fpga/core/laser_pwm.hpp"
#include "fpga/core/step_schedule.hpp"
#include "fpga/rtl_top.hpp"
#include "fpga/top.hpp"
#include "host/core/packet_codec.hpp"
#include "host/sender.hpp"
#include "run/controller.hpp"
#include "run/event_pins.hpp"
#include "run/machine_run.hpp"
#include "run/metrics_feed.hpp"
#include "run/moves.hpp"
#include "uart/cp2102.hpp"
#include "uart/faulty_line.hpp"

namespace cnc::sim::fpga_uart {

namespace {

// The link's wires and the FPGA's internal strobes (the machine's pins are the run's: run/machine.hpp); the VCD
// and the analyze scripts rely on the names (docs/architectures.md "Pins").
struct Wires {
    sc_core::sc_signal<bool> uart_rx{"uart_rx", true};  // CP2102 TXD -> FPGA rx (GPIO_0[0]); idles high
    sc_core::sc_signal<bool> uart_tx{"uart_tx", true};  // FPGA tx (GPIO_0[1]) -> CP2102 RXD
    sc_core::sc_signal<bool> busy{"busy", false};
    sc_core::sc_signal<bool> pkt_valid{"pkt_valid", false}, cfg_valid{"cfg_valid", false};
    sc_core::sc_signal<bool> rx_valid{"rx_valid", false}, ack{"ack", false};
    // With faults on the link: the pins as driven, before the faulty wires (uart/faulty_line.hpp).
    sc_core::sc_signal<bool> cp2102_txd{"cp2102_txd", true}, fpga_tx{"fpga_tx", true};
    // With the FPGA's safety inputs (fpga.estop, fpga.interlock): driven by the scenario's [[events]].
    sc_core::sc_signal<bool> estop{"estop", false}, lid_open{"lid_open", false};
};

// With the laser's PWM: a cut's S in force (none programmed, or a steps-file row: full power, the seed's laser), a
// rapid's 0.
std::optional<std::uint16_t> laser_high_of(const MadeSegment& made, const FpgaUartSettings& f) {
    if (f.fpga.laser_pwm_period_cycles == 0) return std::nullopt;
    if (made.seg.motion == host::MotionKind::Rapid) return 0;
    const std::optional<double> s = made.programmed ? made.programmed->power_s : std::nullopt;
    return fpga::laser_high_cycles(s.value_or(f.laser_s_max), f.laser_s_max, f.fpga.laser_pwm_period_cycles);
}

host::OutgoingPacket packet_of(const MadeSegment& made, InitRegisters n, const FpgaUartSettings& f) {
    const host::MotionPacket packet = host::to_packet(made.seg);
    // The host expects step_gen to use the registers it sends (whether the init packet arrives or not).
    const fpga::MoveInputs move = move_inputs(packet.steps_x, packet.steps_y, packet.feed, n);
    return {host::encode_motion(packet), made.seg.line, fpga::run_duration_ps(move, f.fpga), made.wait_before_s,
            laser_high_of(made, f)};
}

// The sender's packets, made from the job's segments as it asks for them. A segment sent waits here until
// step_gen has run it (the metrics' commanded move); its G-code line until the FPGA's warnings have read it.
class SentPackets : public host::PacketSource {
public:
    // `keep_fields`: every packet's fields and line stay for the fault tally.
    SentPackets(const Scenario& s, const Job& job, InitRegisters n, bool keep_fields)
        : m_settings(s.settings<FpgaUartSettings>()),
          m_segments(s, job),
          m_init_registers(n),
          m_keep_fields(keep_fields) {}

    std::optional<host::OutgoingPacket> next() override {
        std::optional<MadeSegment> made = m_segments.next();
        if (!made) return std::nullopt;
        host::OutgoingPacket packet = packet_of(*made, m_init_registers, m_settings);
        m_lines.push_back(made->seg.line);
        const TimePs t_taken_ps = now_ps();
        if (m_keep_fields) m_sent.push_back({t_taken_ps, made->seg.line, sent_fields(packet)});
        m_unexecuted.push_back({std::move(*made), t_taken_ps});
        return packet;
    }
    double wait_after_last_s() override { return m_segments.wait_after_last_s(); }
    // Once next() has returned none: the programmed moves after the last segment's.
    [[nodiscard]] std::vector<UnsteppedMove> take_unstepped_after_last() {
        return m_segments.take_unstepped_after_last();
    }

    [[nodiscard]] bool unexecuted() const { return !m_unexecuted.empty(); }
    // When the sender took the oldest packet not run yet (unexecuted()); it writes it after that.
    [[nodiscard]] TimePs oldest_taken_ps() const { return m_unexecuted.front().t_taken_ps; }
    // Whether a packet taken after the oldest was taken at or before `t_ps`: then the oldest is no longer in flight.
    [[nodiscard]] bool newer_taken_by(TimePs t_ps) const {
        return m_unexecuted.size() > 1 && m_unexecuted[1].t_taken_ps <= t_ps;
    }
    [[nodiscard]] MadeSegment executed() {  // unexecuted()
        MadeSegment made = std::move(m_unexecuted.front().made);
        m_unexecuted.pop_front();
        return made;
    }
    [[nodiscard]] const RecordLog<int>& lines() const { return m_lines; }  // per packet sent
    void drop_lines_before(std::size_t end) { m_lines.drop_before(end); }
    // With keep_fields: every packet the sender took, in order.
    [[nodiscard]] const std::vector<HostPacket>& sent() const { return m_sent; }

private:
    static fpga::MotionFields sent_fields(const host::OutgoingPacket& packet) {
        const host::MotionPacket p = host::decode_motion(packet.bytes);
        return {p.motion, p.steps_x, p.steps_y, p.feed, 0, packet.laser_high.value_or(0)};
    }

    const FpgaUartSettings& m_settings;
    JobSegments m_segments;
    InitRegisters m_init_registers;
    const bool m_keep_fields;
    std::vector<HostPacket> m_sent;
    struct Unexecuted {
        MadeSegment made;
        TimePs t_taken_ps;
    };
    std::deque<Unexecuted> m_unexecuted;
    RecordLog<int> m_lines;
};

// The executed pieces, one per packet step_gen accepted (a packet ignored because busy carries none), in order:
// busy rises one clock after pkt_valid (SETUP) and falls at DONE. Each record belongs to the packet the sender was
// sending when it arrived (stop-and-wait: the last it took before pkt_valid), so that a packet lost on the link is
// a piece of its own that ran no steps, and a record of a packet already run (a misframed or repeated one) makes
// none: the pieces after them keep their own commanded moves. With the packet queue the host sends ahead and the
// queue takes each packet once, in order: record k is packet k.
class ExecutedPieces {
public:
    explicit ExecutedPieces(bool queued) : m_queued(queued) {}

    // Hands `f` each piece not handed yet whose packet's busy fell before until_ps (none: every accepted packet's,
    // once the run has ended).
    template <typename F>
    void time_ended(const fpga::Board& top, std::optional<TimePs> until_ps, SentPackets& sent, CommandedMoves& moves,
                    F f) {
        const ClockGrid& clock = top.clock();
        for (; m_record < top.packet_count() && sent.unexecuted(); ++m_record) {
            const fpga::PacketRecord r = top.packet(m_record);
            if (!r.accepted) continue;
            if (until_ps && (r.t_busy_fall_ps < 0 || r.t_busy_fall_ps >= *until_ps)) return;
            const TimePs t_begin_ps = clock.at(clock.first_after(r.t_pkt_valid_ps));
            if (!m_queued) {
                while (sent.newer_taken_by(r.t_pkt_valid_ps)) hand_lost(sent.executed(), t_begin_ps, moves, f);
                if (sent.oldest_taken_ps() > r.t_pkt_valid_ps) continue;  // its packet has run already
            }
            const MadeSegment made = sent.executed();
            hand_unstepped(made.unstepped_before, t_begin_ps, moves, f);
            metrics::MoveSpec m = moves.next(made.seg, made.programmed ? &*made.programmed : nullptr);
            m.t_begin_ps = t_begin_ps;
            m.t_end_ps = r.t_busy_fall_ps;
            m_last_end_ps = m.t_end_ps;
            f(std::move(m));
        }
        if (until_ps) return;
        while (sent.unexecuted()) hand_lost(sent.executed(), std::nullopt, moves, f);
        hand_unstepped(sent.take_unstepped_after_last(), std::nullopt, moves, f);
    }

    // The first packet record not read yet.
    [[nodiscard]] std::size_t next_record() const { return m_record; }

private:
    // A packet that never ran: its commanded move with no time of its own, so that it owns no STEP edge.
    template <typename F>
    void hand_lost(const MadeSegment& made, std::optional<TimePs> next_begin_ps, CommandedMoves& moves, F& f) const {
        hand_unstepped(made.unstepped_before, next_begin_ps, moves, f);
        metrics::MoveSpec m = moves.next(made.seg, made.programmed ? &*made.programmed : nullptr);
        place_unstepped(m, next_begin_ps, m_last_end_ps);
        f(std::move(m));
    }

    template <typename F>
    void hand_unstepped(const std::vector<UnsteppedMove>& unstepped, std::optional<TimePs> next_begin_ps,
                        CommandedMoves& moves, F& f) const {
        for (const UnsteppedMove& u : unstepped) {
            metrics::MoveSpec m = moves.unstepped(u.programmed, u.move);
            place_unstepped(m, next_begin_ps, m_last_end_ps);
            f(std::move(m));
        }
    }

    const bool m_queued;
    std::size_t m_record = 0;
    TimePs m_last_end_ps = 0;  // the last piece's
};

// A steps file's FeedRate 0 (seed 000's text divides by the feed, §3.4.5, so it allows 1 .. 65535; the appendix
// RTL would run 0 as 62500 clocks per step) is sent only when the scenario asks for it.
void check_steps_feeds(const Scenario& s, const Job& job, const FpgaUartSettings& f) {
    if (f.allow_feed_zero) return;
    for (const host::MotionSegment& seg : job.steps_file) {
        if (seg.feed == 0) {
            throw BadInput(s.job_path + ": segment " + std::to_string(seg.index),
                           "FeedRate 0 (allowed 1 .. 65535; host.allow_feed_zero = true sends it as the appendix "
                           "RTL would run it: 62500 clocks per step on both axes)");
        }
    }
}

// Before anything is simulated: every segment made and encoded once (the CAM's and the packet codec's BadInput),
// counted for the job's pace.
std::size_t count_packets(const Scenario& s, const Job& job, InitRegisters n) {
    const FpgaUartSettings& f = s.settings<FpgaUartSettings>();
    JobSegments segments(s, job);
    std::size_t count = 0;
    for (std::optional<MadeSegment> made = segments.next(); made; made = segments.next()) {
        (void)packet_of(*made, n, f);
        ++count;
    }
    return count;
}

// "segment 17 (line 20)": the packet's number, and its G-code line when the job was G-code.
std::string segment_place(const RecordLog<int>& lines, std::size_t k) {
    std::string where = "segment " + std::to_string(k + 1);
    if (k < lines.size() && lines[k] > 0) where += " (line " + std::to_string(lines[k]) + ")";
    return where;
}

// FPGA-side warnings: the period product the RTL cannot hold and packets lost while busy, read packet by packet
// as step_gen sees them (what they read of a packet is final then), so that the records can go; then the init
// packets and the line faults, at the end.
class FpgaWarnings {
public:
    explicit FpgaWarnings(const FpgaUartSettings& f)
        : m_settings(f),
          m_overflow(std::string("(NUMERATOR/feed) x dominant steps exceeds 32 bits; step_gen as printed in the "
                                 "appendix wraps it") +
                     (f.fpga.period_arithmetic == fpga::PeriodArithmetic::Wrap32
                          ? " (fpga.period_arithmetic = wrap32: this run used the wrapped period)"
                          : " (this run used the exact period; fpga.period_arithmetic = wrap32 reproduces the wrap)")) {
    }

    // Reads the packets step_gen has seen since the last call.
    void read(const fpga::Board& top, const RecordLog<int>& lines) {
        const TimePs halted_ps = top.stats().halted_at_ps;
        for (; m_next < top.packet_count(); ++m_next) {
            const fpga::PacketRecord r = top.packet(m_next);
            if (r.period_overflow) m_packets.push_back({"period_overflow", segment_place(lines, m_next), m_overflow});
            if (!r.accepted) {
                const bool after_halt = halted_ps >= 0 && r.t_pkt_valid_ps >= halted_ps;
                m_packets.push_back({"packet_lost", segment_place(lines, m_next),
                                     after_halt ? "arrived after the e-stop halted step_gen: not run"
                                                : "arrived while step_gen was busy: lost"});
            }
        }
    }
    // The first packet not read yet.
    [[nodiscard]] std::size_t next_packet() const { return m_next; }
    // Every packet read: their warnings, then the init packets' and the FPGA's counters'.
    void finish(const fpga::Board& top, std::vector<Warning>& warnings) const;

private:
    const FpgaUartSettings& m_settings;
    const std::string m_overflow;
    std::vector<Warning> m_packets;
    std::size_t m_next = 0;
};

void FpgaWarnings::finish(const fpga::Board& top, std::vector<Warning>& warnings) const {
    const FpgaUartSettings& f = m_settings;
    warnings.insert(warnings.end(), m_packets.begin(), m_packets.end());
    for (const fpga::InitRecord& i : top.inits()) {
        if (!i.applied) {
            const char* why = f.fpga.init_packet_wired ? " (step_gen was busy)"
                                                       : " (fpga.init_packet_wired = false, as appendix top.v)";
            warnings.push_back({"init_not_applied", "",
                                "init packet (NUMERATOR " + std::to_string(i.num_x) + "/" + std::to_string(i.num_y) +
                                    ") did not reach step_gen" + why});
        }
    }
    if (!top.records_from_nets()) {
        warnings.push_back(
            {"fpga_records_from_pins", "",
             "the FPGA design lacks our top's nets (pkt_valid, step_gen_inst.state, ...): each busy "
             "pulse is taken for a packet, the FPGA's byte, framing and watchdog counters are not known"});
    }
    const fpga::FpgaStats st = top.stats();
    if (st.framing_errors > 0) {
        warnings.push_back(
            {"fpga_framing_errors", "", std::to_string(st.framing_errors) + " UART framing errors at the FPGA"});
    }
    if (st.watchdog_resets > 0) {
        warnings.push_back(
            {"watchdog_resets", "", std::to_string(st.watchdog_resets) + " packet_decoder watchdog resets"});
    }
    if (st.acks_dropped > 0) {
        warnings.push_back({"acks_dropped", "", std::to_string(st.acks_dropped) + " ACKs dropped (uart_tx busy)"});
    }
}

constexpr const char* kDeadTimeNotSplit =
    "dead time not split into its causes: the link has faults, and a lost or repeated packet breaks the reading of "
    "one gap per packet";
constexpr const char* kQueuedNotSplit =
    "dead time not split into its causes: the packet queue sends ahead, so a gap is no turn of the stop-and-wait loop "
    "(the metrics' job dead time measures the gaps)";

// The models' per-packet records that every reader has read go: the metrics' pieces, the dead-time split and the
// warnings read them once. The detailed report lists every packet step_gen saw and the sender sent, and the fault
// tally pairs them at the end: kept.
void hand_over_read(const ExecutedPieces& executed, const DeadTimeFold& dead_fold, const FpgaWarnings& warnings,
                    const RampCommanded* ramp, bool keep_packets, fpga::Board& fpga, host::Sender& sender,
                    uart::Cp2102& cp2102, SentPackets& packets) {
    cp2102.drop_tx_log_before(dead_fold.next_packet());
    cp2102.drop_rx_log_before(dead_fold.next_rx_byte());
    packets.drop_lines_before(warnings.next_packet());
    if (keep_packets) return;
    fpga.drop_packets_before(std::min({executed.next_record(), dead_fold.next_packet(), warnings.next_packet(),
                                       ramp != nullptr ? ramp->next_record() : executed.next_record()}));
    sender.drop_packets_before(dead_fold.next_packet());
}

// The fpga-uart side of the job estimate: send_steps.py's settle and init gap, then per packet its trip over
// the link: the host's work and write latency, the USB frames out and in, the driver latency, and the packet
// and its ACK on the line (4.3 ms at 115200 Bd; the run's dead-time split measures 4.35 ms per gap on the square: docs/usage.md).
ArchPace pace(const Scenario& s, const FpgaUartSettings& f, std::size_t packets) {
    constexpr double kBitsPerByte = 10.0;                          // 8N1
    constexpr double kTripBytes = host::kMotionPacketBytes + 1.0;  // the packet and its ACK
    ArchPace p;
    p.max_speed_x_mm_per_s = s.machine.x.limits.max_velocity_mm_per_s;  // the CAM holds the packet feed to them
    p.max_speed_y_mm_per_s = s.machine.y.limits.max_velocity_mm_per_s;
    p.startup_s = ps_to_s(f.serial.sender.settle_ps + f.serial.sender.init_gap_ps);
    const double trip_s = ps_to_s(f.serial.sender.packet_processing_ps + f.serial.sender.write_latency_ps +
                                  2 * f.serial.link.usb_frame_ps + f.serial.link.usb_latency_ps) +
                          kTripBytes * kBitsPerByte / static_cast<double>(f.serial.link.requested_baud);
    p.link_s = static_cast<double>(packets) * trip_s;
    if (f.fpga.ramp != fpga::StepRamp::None) {
        const double accel = std::min(s.machine.x.limits.max_accel_mm_per_s2, s.machine.y.limits.max_accel_mm_per_s2);
        if (f.fpga.ramp == fpga::StepRamp::SCurve) {
            // The S-curve's ramps take T = dv / a + a / j each (2 sqrt(dv / j) below dv = a^2 / j), with the mean
            // speed of the trapezoid's: T (v - v0) / v.
            const double jerk = std::min(s.machine.x.limits.max_jerk_mm_per_s3, s.machine.y.limits.max_jerk_mm_per_s3);
            p.ramp_s = [accel, jerk, v0 = f.ramp_start_mm_per_s](double v) {
                if (v <= v0) return 0.0;
                const double dv = v - v0;
                const double ramp_s = dv >= accel * accel / jerk ? dv / accel + accel / jerk : 2 * std::sqrt(dv / jerk);
                return ramp_s * dv / v;
            };
        } else {
            // Each move starts and ends at the start speed: up and down at the slower axis' acceleration add
            // (v - v0)^2 / (a v) to length / v.
            p.ramp_s = [accel, v0 = f.ramp_start_mm_per_s](double v) {
                return v > v0 ? (v - v0) * (v - v0) / (accel * v) : 0.0;
            };
        }
    }
    return p;
}

// A steps file has no programmed moves: its packets, as the straight lines they are, at the speed step_gen
// runs them (so also a FeedRate 0 row of host.allow_feed_zero).
host::Program packet_moves(const std::vector<host::MotionSegment>& rows, InitRegisters n, const Scenario& s,
                           const FpgaUartSettings& f) {
    host::Program program;
    program.filename = s.job_path;
    geom::Vec2 at{};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const geom::Vec2 to = at + geom::Vec2{rows[i].dx_mm, rows[i].dy_mm};
        const double run_s = ps_to_s(packet_of({rows[i], std::nullopt, 0.0, {}}, n, f).expected_run_ps);
        // A packet step_gen does not run (no steps, or a period of 0) takes no time at any feed.
        const double feed_mm_per_min =
            run_s > 0.0 ? geom::distance(at, to) / run_s * kSecondsPerMinute : std::numeric_limits<double>::infinity();
        host::ProgrammedMove move{};
        move.kind = rows[i].motion;
        move.path = geom::Segment::line(at, to);
        move.feed_mm_per_min = feed_mm_per_min;
        move.laser_on = rows[i].motion != host::MotionKind::Rapid;
        move.line = rows[i].line;
        program.moves.push_back(move);
        at = to;
    }
    program.move_count = program.moves.size();
    return program;
}

// The job's estimate: a G-code job's moves read from the file once more (the summary has none).
JobEstimate estimate(const Scenario& s, const FpgaUartSettings& f, const Job& job, InitRegisters n,
                     const ArchPace& pace) {
    if (!job.program) return estimate_job(packet_moves(job.steps_file, n, s, f), pace);
    host::GcodeStream moves(s.job_path, s.interpreter, false);
    EstimateSum sum(job.program->wait_s_between(0, job.program->move_count + 1), pace);
    for (std::optional<host::ProgrammedMove> m = moves.next(); m; m = moves.next()) sum.add(*m);
    return sum.finish();
}

nlohmann::json packet_json(const fpga::PacketRecord& r) {
    return {
        {"t_pkt_valid_s", ps_to_s(r.t_pkt_valid_ps)},
        {"motion", r.motion},
        {"steps", {r.steps_x, r.steps_y}},
        {"feed", r.feed},
        {"accepted", r.accepted},
        {"period_cycles", {r.period_x_cycles, r.period_y_cycles}},
        {"period_overflow", r.period_overflow},
        {"t_run_start_s", ps_to_s(r.t_run_start_ps)},
        {"t_busy_fall_s", ps_to_s(r.t_busy_fall_ps)},
        {"t_ack_start_s", r.t_ack_start_ps < 0 ? nlohmann::json(nullptr) : nlohmann::json(ps_to_s(r.t_ack_start_ps))}};
}

nlohmann::json sent_json(const host::SentPacket& p) {
    return {{"segment", p.segment},
            {"t_write_s", ps_to_s(p.t_write_ps)},
            {"t_ack_s", p.t_ack_ps < 0 ? nlohmann::json(nullptr) : nlohmann::json(ps_to_s(p.t_ack_ps))},
            {"timed_out", p.timed_out}};
}

// The FPGA UART's rate (clock / FULL_BIT) against the CP2102's, before anything is simulated.
void check_fpga_rate(const Scenario& s, const FpgaUartSettings& f) {
    const double fpga_bd = static_cast<double>(f.fpga.clk_hz) / f.fpga.uart_full_bit_cycles;
    check_line_rates(
        s.file + ": link.baud, fpga.uart_baud", cp2102_end(f.serial.link),
        {fpga_bd, fmt::format(FMT_STRING("the FPGA UART at {:.2f} Bd (fpga.uart_baud: {:g} MHz / {} clocks a bit)"),
                              fpga_bd, f.fpga.clk_hz / 1e6, f.fpga.uart_full_bit_cycles)});
}

// The script as the scenario sets it, with the host stall of its faults.
host::SenderConfig sender_config(const Scenario& s, const FpgaUartSettings& f) {
    host::SenderConfig c = f.serial.sender;
    c.queue_depth = f.fpga.queue_depth;
    c.stall = stall_window(s.faults.host_stall);
    return c;
}

// The FPGA as the scenario asks: the event-driven blocks, or the Verilog in the loop running ahead to the time
// before which its inputs cannot change (`rx_quiet_until`: rx's and the safety inputs').
std::unique_ptr<fpga::Board> make_fpga(const FpgaUartSettings& f, std::uint64_t seed,
                                       std::function<TimePs()> rx_quiet_until, Wires& wires) {
    const fpga::FpgaConfig cfg = on_oscillator(f.fpga, f.clock, seed);
    std::unique_ptr<fpga::Board> board;
    if (!f.rtl.rtl) {
        board = std::make_unique<fpga::Top>("fpga", cfg);
    } else {
        auto rtl = std::make_unique<fpga::RtlTop>("fpga", cfg, f.rtl.design);
        rtl->rx_quiet_until(std::move(rx_quiet_until));
        board = std::move(rtl);
    }
    if (cfg.estop_input) board->estop(wires.estop);
    if (cfg.interlock_input) board->lid_open(wires.lid_open);
    return board;
}

// The seed 000 system between the job and the machine's pins: the CAM (GCODE2STEPS) on the host, or the steps file
// it wrote, send_steps.py through the CP2102, the FPGA.
class FpgaUartController final : public Controller {
public:
    // `n` and `packet_count`: checked_packets().
    FpgaUartController(const Scenario& s, const Job& job, MachinePins& pins, InitRegisters n, std::size_t packet_count)
        : m_s(s),
          m_f(s.settings<FpgaUartSettings>()),
          m_job(job),
          m_init_registers(n),
          m_packet_count(packet_count),
          m_cp2102("cp2102", with_usb_spikes(m_f.serial.link, s.faults)),
          m_packets(s, job, m_init_registers, s.faults.any()),
          m_sender("host", sender_config(s, m_f), m_cp2102, init_packet(m_init_registers, m_f), m_packets),
          m_fpga(make_fpga(
              m_f, s.seed, [this] { return rx_quiet_until(); }, m_wires)),
          m_event_pins("event_pins", s.events, m_wires.estop, m_wires.lid_open),
          m_moves(s.machine, s.interpreter.start_mm),
          // Every gap only for the detailed report and the plots (which keep the whole run anyway).
          m_dead_fold(s.detail || s.keep_run_input),
          m_executed(m_f.fpga.queue_depth > 0),
          m_warnings(m_f),
          m_rate_feed(s.detail) {
        if (m_f.fpga.ramp != fpga::StepRamp::None) {
            m_ramp = std::make_unique<RampCommanded>(
                m_f.fpga, m_init_registers, s.interpreter.start_mm,
                std::array<double, 2>{s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()});
        }
        const std::size_t check_bytes = m_f.serial.sender.check.crc ? host::kCrcBytes : 0;
        const std::size_t pwm_bytes = m_f.fpga.laser_pwm_period_cycles > 0 ? host::kLaserHighBytes : 0;
        m_cp2102.thin_tx_log(init_packet(m_init_registers, m_f).size() + check_bytes,  // what the dead-time split reads
                             host::kMotionPacketBytes + pwm_bytes + check_bytes);
        m_fpga->rx(m_wires.uart_rx);
        m_cp2102.rxd(m_wires.uart_tx);
        if (s.faults.uart.any()) {
            wire_faulty_lines();
        } else {
            m_cp2102.txd(m_wires.uart_rx);
            m_fpga->tx(m_wires.uart_tx);
        }
        m_fpga->dir_x(pins.dir_x);
        m_fpga->step_x(pins.step_x);
        m_fpga->dir_y(pins.dir_y);
        m_fpga->step_y(pins.step_y);
        m_fpga->laser(pins.laser);
        m_fpga->busy(m_wires.busy);
        m_fpga->pkt_valid(m_wires.pkt_valid);
        m_fpga->cfg_valid(m_wires.cfg_valid);
        m_fpga->rx_valid(m_wires.rx_valid);
        m_fpga->tx_start(m_wires.ack);
    }

    // The FPGA times everything it drives and drives no EN pin; the CP2102 (uart_rx) starts its frames when USB
    // delivers the bytes.
    [[nodiscard]] MachinePinClocks pin_clocks() const override { return {m_fpga->clock().grid_hz(), std::nullopt}; }
    [[nodiscard]] std::vector<TracedPin> traced_pins() const override {
        const std::optional<std::int64_t> fpga = m_fpga->clock().grid_hz();
        const Wires& w = m_wires;
        std::vector<TracedPin> pins = {{&w.uart_rx, "link", {}},     {&w.uart_tx, "link", fpga},
                                       {&w.busy, "fpga", fpga},      {&w.pkt_valid, "fpga", fpga},
                                       {&w.cfg_valid, "fpga", fpga}, {&w.rx_valid, "fpga", fpga},
                                       {&w.ack, "fpga", fpga}};
        if (m_f.fpga.estop_input) pins.push_back({&w.estop, "fpga", {}});
        if (m_f.fpga.interlock_input) pins.push_back({&w.lid_open, "fpga", {}});
        return pins;
    }
    // The link's lines and busy go into ArchRun::lines only when the whole logs are kept (--plots, --samples,
    // tests): a long job's UART lines are its largest log after the STEPs, and no metric reads them.
    void record(EdgeRecorder& rec, bool whole_logs) override {
        m_whole_logs = whole_logs;
        if (!whole_logs) return;
        for (const sc_core::sc_signal<bool>* sig : {&m_wires.busy, &m_wires.uart_rx, &m_wires.uart_tx}) {
            rec.watch(*sig, sig->basename());
        }
    }

    [[nodiscard]] JobEstimate estimate() const override {
        return fpga_uart::estimate(m_s, m_f, m_job, m_init_registers, pace(m_s, m_f, m_packet_count));
    }
    // The dead-time split reads each piece's first and last STEP: handed to it as the stream measures the pieces,
    // and it folds each gap once final.
    [[nodiscard]] metrics::PieceMeasured on_piece_measured() override {
        return [this](const metrics::MoveMetrics& p) {
            if (p.index != 0) m_dead_fold.add_piece(piece_steps(p));  // one per packet: not a move too short to step
        };
    }
    void feed_started(MetricsFeed& feed) override {
        if (m_ramp) feed.pending().commanded = m_ramp->trajectory(0);
    }
    void slice_ended(TimePs now_ps, MetricsFeed* feed) override {
        if (feed == nullptr) return;
        m_executed.time_ended(*m_fpga, now_ps, m_packets, m_moves,
                              [&](metrics::MoveSpec m) { feed->add_piece(std::move(m)); });
        hand_over_ramp(*feed, now_ps);
        feed->fold(now_ps);
        if (split_dead_time()) m_dead_fold.fold(now_ps, false, *m_fpga, m_sender.packets(), m_cp2102);
        m_warnings.read(*m_fpga, m_packets.lines());
        hand_over_read(m_executed, m_dead_fold, m_warnings, m_ramp.get(), m_s.detail || m_s.faults.any(), *m_fpga,
                       m_sender, m_cp2102, m_packets);
    }

    [[nodiscard]] TimePs job_end_ps(TimePs stop_ps) const override {
        return m_sender.finished() ? m_sender.t_end_ps() : stop_ps;
    }
    void finish_feed(MetricsFeed& feed) override {
        m_executed.time_ended(*m_fpga, std::nullopt, m_packets, m_moves,
                              [&](metrics::MoveSpec m) { feed.add_piece(std::move(m)); });
        hand_over_ramp(feed, kEndOfRun);
    }
    void finish_input(metrics::RunInput& in, bool streamed) override {
        if (streamed) {
            if (m_ramp) in.rate_segments = m_rate_feed.take_kept();
            return;
        }
        m_executed.time_ended(*m_fpga, std::nullopt, m_packets, m_moves,
                              [&](metrics::MoveSpec m) { in.moves.push_back(std::move(m)); });
        if (!m_ramp) return;
        m_ramp->read(*m_fpga, kEndOfRun);
        in.commanded = m_ramp->trajectory(kEndOfRun);
        in.rate_segments = m_ramp->take_segments();
    }
    void measured(const metrics::RunMetrics& m) override {
        for (const metrics::MoveMetrics& p : m.pieces) m_dead_fold.add_piece(piece_steps(p));
    }
    void take_lines(EdgeRecorder& rec, std::map<std::string, EdgeLog>& lines) override {
        if (!m_whole_logs) return;
        for (const char* pin : {"busy", "uart_rx", "uart_tx"}) lines[pin] = rec.take(pin);
    }
    void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) override;

private:
    static constexpr TimePs kEndOfRun = std::numeric_limits<TimePs>::max();

    // With the ramp: the moves step_gen has begun by now_ps, as the commanded trajectory (known to now_ps) and
    // their steps' rate segments.
    void hand_over_ramp(MetricsFeed& feed, TimePs now_ps) {
        if (!m_ramp) return;
        m_ramp->read(*m_fpga, now_ps);
        m_rate_feed.hand_over(feed, m_ramp->take_segments());
        feed.pending().commanded->t_end_ps = now_ps;
    }

    // Each wire through its faults, drawn apart (line 0 to the FPGA, 1 from it) and timed by its sender's bit clock.
    void wire_faulty_lines() {
        const uart::LineFaultRates& rates = m_s.faults.uart;
        const std::uint64_t seed = m_s.faults.seed;
        m_to_fpga_line =
            std::make_unique<uart::FaultyLine>("to_fpga_line", rates, seed, 0, m_cp2102.baud().bit_clock());
        m_from_fpga_line = std::make_unique<uart::FaultyLine>(
            "from_fpga_line", rates, seed, 1, uart::BitClock{m_f.fpga.uart_full_bit_cycles, m_f.fpga.clk_hz});
        m_cp2102.txd(m_wires.cp2102_txd);
        m_to_fpga_line->in(m_wires.cp2102_txd);
        m_to_fpga_line->out(m_wires.uart_rx);
        m_fpga->tx(m_wires.fpga_tx);
        m_from_fpga_line->in(m_wires.fpga_tx);
        m_from_fpga_line->out(m_wires.uart_tx);
    }
    // The CP2102's promise for its TXD, through the faulty wire if there is one (an inverted bit changes rx where
    // TXD does not), and the next of the scenario's events.
    [[nodiscard]] TimePs rx_quiet_until() const {
        const TimePs txd = m_cp2102.txd_quiet_until();
        return std::min(m_to_fpga_line ? m_to_fpga_line->out_quiet_until(txd) : txd, m_event_pins.quiet_until_ps());
    }
    void report_faults(ArchRun& run, std::ostringstream& text) const;
    // The split reads gap k between packets k and k+1 as each packet runs once: not so on a link with faults (a host
    // stall keeps it so: its time shows as the host's).
    [[nodiscard]] bool split_dead_time() const { return !m_s.faults.uart.any() && m_f.fpga.queue_depth == 0; }
    [[nodiscard]] const char* why_not_split() const {
        return m_f.fpga.queue_depth > 0 ? kQueuedNotSplit : kDeadTimeNotSplit;
    }

    const Scenario& m_s;
    const FpgaUartSettings& m_f;
    const Job& m_job;
    InitRegisters m_init_registers;
    std::size_t m_packet_count;
    Wires m_wires;
    uart::Cp2102 m_cp2102;
    SentPackets m_packets;
    host::Sender m_sender;
    std::unique_ptr<fpga::Board> m_fpga;
    EventPins m_event_pins;
    CommandedMoves m_moves;
    DeadTimeFold m_dead_fold;
    ExecutedPieces m_executed;
    FpgaWarnings m_warnings;
    std::unique_ptr<uart::FaultyLine> m_to_fpga_line;
    std::unique_ptr<uart::FaultyLine> m_from_fpga_line;
    RateSegmentFeed m_rate_feed;
    std::unique_ptr<RampCommanded> m_ramp;  // with the ramp
    bool m_whole_logs = false;
};

void FpgaUartController::report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) {
    const Scenario& s = m_s;
    const metrics::RunInput& in = run.input;
    if (split_dead_time()) m_dead_fold.fold(in.t_job_end_ps, true, *m_fpga, m_sender.packets(), m_cp2102);
    const DeadTimeBreakdown dead = m_dead_fold.finish(in.t_job_start_ps, in.t_job_end_ps, m_cp2102);
    if (s.keep_run_input) run.gap_causes = gap_causes(dead);

    m_warnings.read(*m_fpga, m_packets.lines());
    m_warnings.finish(*m_fpga, run.warnings);
    const fpga::FpgaStats st = m_fpga->stats();
    const uart::Cp2102Baud& baud = m_cp2102.baud();
    run.clock = oscillator_json(m_f.clock, m_fpga->clock());
    run.clock_text = oscillator_text(m_f.clock, m_fpga->clock());
    nlohmann::json msgs = nlohmann::json::array();
    for (const host::SenderMessage& m : m_sender.messages()) {
        msgs.push_back({{"t_s", ps_to_s(m.t_ps)}, {"text", m.text}});
    }
    run.details = {{"segments", m_packet_count},
                   {"link",
                    {{"requested_baud", m_f.serial.link.requested_baud},
                     {"line_baud", baud.actual_bd},
                     {"line_baud_error_pct", baud.error_pct},
                     {"fpga_bit_cycles", m_f.fpga.uart_full_bit_cycles},
                     {"bytes_to_fpga", m_cp2102.stats().tx_bytes},
                     {"bytes_from_fpga", m_cp2102.rx_log().size()},
                     {"utilisation_to_fpga_pct", dead.utilisation_to_fpga_pct},
                     {"utilisation_from_fpga_pct", dead.utilisation_from_fpga_pct}}},
                   {"sender",
                    {{"packets_sent", m_sender.packets().size()},
                     {"errors", m_sender.errors()},
                     {"aborted", m_sender.aborted()},
                     {"finished", m_sender.finished()},
                     {"t_end_s", ps_to_s(m_sender.t_end_ps())},
                     {"messages", msgs}}},
                   {"fpga",
                    {{"bytes_received", st.bytes_received},
                     {"framing_errors", st.framing_errors},
                     {"watchdog_resets", st.watchdog_resets},
                     {"acks_sent", st.acks_sent},
                     {"acks_dropped", st.acks_dropped}}},
                   {"dead_time", split_dead_time() ? to_json(dead, s.detail) : nlohmann::json(why_not_split())}};
    if (m_f.fpga.estop_input) {
        run.details["fpga"]["halted_at_s"] =
            st.halted_at_ps < 0 ? nlohmann::json(nullptr) : nlohmann::json(ps_to_s(st.halted_at_ps));
    }
    if (m_f.fpga.queue_depth > 0) {
        run.details["queue"] = {{"depth", m_f.fpga.queue_depth},
                                {"queued", st.queued},
                                {"answered_again", st.answered_again},
                                {"refused", st.refused},
                                {"statuses_sent", st.statuses_sent},
                                {"host_sent_again", m_sender.resends()},
                                {"host_polls", m_sender.polls()},
                                {"host_stray_bytes", m_sender.stray_bytes()},
                                {"host_bad_statuses", m_sender.bad_statuses()}};
    }
    if (s.detail) {  // one record per packet: they grow with the job
        nlohmann::json& sent = run.details["sender"]["packets"] = nlohmann::json::array();
        for (const host::SentPacket& p : m_sender.packets()) sent.push_back(sent_json(p));
        nlohmann::json& received = run.details["fpga"]["packets"] = nlohmann::json::array();
        for (std::size_t k = 0; k < m_fpga->packet_count(); ++k) received.push_back(packet_json(m_fpga->packet(k)));
    }

    std::ostringstream text;
    text << "fpga-uart link and host\n"
         << fmt::format(FMT_STRING("  line {:.1f} Bd ({:+.3f} % vs requested), FPGA bit {} clocks\n"), baud.actual_bd,
                        baud.error_pct, m_f.fpga.uart_full_bit_cycles)
         << "  packets sent " << m_sender.packets().size() << ", ACK timeouts " << m_sender.errors() << ", FPGA ACKs "
         << st.acks_sent << " (dropped " << st.acks_dropped << ")\n"
         << (split_dead_time() ? summary_text(dead) : std::string("  ") + why_not_split() + "\n");
    if (m_f.fpga.queue_depth > 0) {
        text << fmt::format(FMT_STRING("  packet queue of {}: {} queued, {} answered again, {} refused, {} statuses; "
                                       "host sent {} again, polled {} times\n"),
                            m_f.fpga.queue_depth, st.queued, st.answered_again, st.refused, st.statuses_sent,
                            m_sender.resends(), m_sender.polls());
    }
    for (const host::SenderMessage& m : m_sender.messages()) {
        text << fmt::format(FMT_STRING("  host at {:.6f} s: {}\n"), ps_to_s(m.t_ps), m.text);
    }
    if (m_s.faults.any()) report_faults(run, text);
    run.details_text = text.str();
    report_usb_spikes(m_s.faults, m_cp2102, run);

    // Framing errors are what faults on the line make: reported above, not a failed run.
    const std::optional<std::string> framing =
        m_s.faults.uart.any()
            ? std::nullopt
            : framing_failure(static_cast<std::int64_t>(st.framing_errors), "FPGA", m_cp2102.stats().framing_errors);
    if (framing) {
        run.ok = false;
        run.failure = *framing;
    } else if (m_sender.halted()) {
        run.ok = false;
        run.failure = fmt::format(FMT_STRING("the e-stop halted the FPGA at {:.6f} s ({}); send_steps.py stops here"),
                                  ps_to_s(st.halted_at_ps), m_sender.abort_reason());
    } else if (m_sender.aborted()) {
        run.ok = false;
        run.failure =
            "ACK timeout at " + m_sender.abort_reason() + "; send_steps.py stops here (host.on_timeout = abort)";
    } else if (!m_sender.finished()) {
        run.ok = false;
        run.failure = "the job did not finish: " + time_limit_text(budget, end);
    }
}

nlohmann::json fields_json(const fpga::MotionFields& f) {
    return {{"motion", f.motion}, {"steps", {f.steps_x, f.steps_y}}, {"feed", f.feed}};
}

// Every packet sent against what step_gen ran (packet_faults.hpp), what detected the faults, and the steps they
// left at the job's end.
void FpgaUartController::report_faults(ArchRun& run, std::ostringstream& text) const {
    std::vector<FpgaPacket> received;
    for (std::size_t k = 0; k < m_fpga->packet_count(); ++k) {
        const fpga::PacketRecord r = m_fpga->packet(k);
        received.push_back({r.t_pkt_valid_ps, r.accepted, {r.motion, r.steps_x, r.steps_y, r.feed}});
    }
    const PacketFaults f = packet_faults(m_packets.sent(), received, m_f.fpga.queue_depth > 0);
    const fpga::FpgaStats st = m_fpga->stats();
    const uart::FaultyLineStats to = m_to_fpga_line ? m_to_fpga_line->stats() : uart::FaultyLineStats{};
    const uart::FaultyLineStats from = m_from_fpga_line ? m_from_fpga_line->stats() : uart::FaultyLineStats{};
    const HostStall& stall = m_s.faults.host_stall;
    nlohmann::json silent = nlohmann::json::array();
    for (const SilentCorruption& c : f.silent) {
        silent.push_back({{"segment", c.segment},
                          {"line", c.gcode_line},
                          {"sent", fields_json(c.sent)},
                          {"executed", fields_json(c.executed)},
                          {"error_steps", c.error_steps}});
    }
    run.details["faults"] = {{"seed", m_s.faults.seed},
                             {"uart_ber", m_s.faults.uart.ber},
                             {"uart_frame_loss_rate", m_s.faults.uart.frame_loss_rate},
                             {"to_fpga", faulty_line_json(to)},
                             {"from_fpga", faulty_line_json(from)},
                             {"host_stall", host_stall_json(stall, m_sender.stalled_ps())},
                             {"packets",
                              {{"sent", f.sent},
                               {"executed_as_sent", f.executed_as_sent},
                               {"silently_executed_wrong", f.executed_wrong},
                               {"lost", f.lost},
                               {"extra", f.extra},
                               {"ignored_while_busy", f.ignored}}},
                             {"detected",
                              {{"fpga_framing_errors", st.framing_errors},
                               {"watchdog_resets", st.watchdog_resets},
                               {"crc_errors", st.crc_errors},
                               {"host_ack_timeouts", m_sender.errors()},
                               {"host_framing_errors", m_cp2102.stats().framing_errors}}},
                             {"retransmitted", m_sender.resends()},
                             {"naks", {{"sent", st.naks_sent}, {"read", m_sender.naks()}}},
                             {"repeats_acked", st.repeats},
                             {"job_end_error_steps", f.job_end_error_steps},
                             {"commands_run_changed", f.executed_wrong},
                             {"silent", silent}};
    text << fmt::format(FMT_STRING("faults (seed {}): UART BER {:g}, frames lost {:g}\n"), m_s.faults.seed,
                        m_s.faults.uart.ber, m_s.faults.uart.frame_loss_rate)
         << fmt::format(FMT_STRING("  to the FPGA: {} of {} frames hit ({} lost, {} bits inverted); from it: {} of {} "
                                   "({} lost, {} bits)\n"),
                        to.frames_hit, to.frames, to.frames_lost, to.bits_inverted, from.frames_hit, from.frames,
                        from.frames_lost, from.bits_inverted)
         << fmt::format(
                FMT_STRING("  packets: {} sent, {} run as sent, {} run wrong without a check noticing, {} lost, "
                           "{} extra\n"),
                f.sent, f.executed_as_sent, f.executed_wrong, f.lost, f.extra)
         << fmt::format(FMT_STRING("  detected: {} framing errors, {} watchdog resets and {} bad CRCs at the FPGA, {} "
                                   "ACK timeouts at the host; sent again: {}\n"),
                        st.framing_errors, st.watchdog_resets, st.crc_errors, m_sender.errors(), m_sender.resends())
         << fmt::format(FMT_STRING("  steps off at the job's end: X {:+d}, Y {:+d}\n"), f.job_end_error_steps[0],
                        f.job_end_error_steps[1]);
    if (stall.any()) text << host_stall_text(stall, m_sender.stalled_ps());
    constexpr std::size_t kListed = 20;  // the report's faults.silent has them all
    for (std::size_t k = 0; k < std::min(f.silent.size(), kListed); ++k) {
        const SilentCorruption& c = f.silent[k];
        text << fmt::format(FMT_STRING("  segment {}{}: sent {} {} {} F{}, ran {} {} {} F{}: X {:+d}, Y {:+d} steps\n"),
                            c.segment, c.gcode_line > 0 ? " (line " + std::to_string(c.gcode_line) + ")" : "",
                            c.sent.motion, c.sent.steps_x, c.sent.steps_y, c.sent.feed, c.executed.motion,
                            c.executed.steps_x, c.executed.steps_y, c.executed.feed, c.error_steps[0],
                            c.error_steps[1]);
    }
    if (f.silent.size() > kListed) text << "  ... and " << f.silent.size() - kListed << " more\n";
}

}  // namespace

ArchRun Entry::run(const Scenario& s, const Job& job) {
    return run_on_machine(s, job, [](const Scenario& sc, const Job& j, MachinePins& pins) {
        const FpgaUartSettings& f = sc.settings<FpgaUartSettings>();
        check_steps_feeds(sc, j, f);
        const InitRegisters n = init_registers(sc, f);
        const std::size_t packet_count = count_packets(sc, j, n);
        check_fpga_rate(sc, f);
        return std::make_unique<FpgaUartController>(sc, j, pins, n, packet_count);
    });
}

}  // namespace cnc::sim::fpga_uart
