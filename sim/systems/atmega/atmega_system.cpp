#include "systems/atmega/atmega_system.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "avr/avr_core.hpp"
#include "common/bad_input.hpp"
#include "common/text_format.hpp"
#include "host/core/seed003/firmware_busy.hpp"
#include "host/pc_program.hpp"
#include "probes/edge_recorder.hpp"
#include "probes/vcd_trace.hpp"
#include "systems/carriage_feed.hpp"
#include "run/moves.hpp"
#include "run/simulate.hpp"
#include "systems/atmega/atmega_report.hpp"
#include "systems/atmega/chord_gaps.hpp"
#include "systems/atmega/link_bytes.hpp"
#include "systems/atmega/firmware_usart.hpp"
#include "systems/atmega/atmega_pins.hpp"
#include "systems/link_checks.hpp"
#include "systems/machine.hpp"
#include "systems/mechanics_report.hpp"
#include "uart/core/line_receiver.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

namespace {

namespace s3 = host::seed003;

// The chip's timers run on after M30 (cli; sleep): the run ends when the firmware has stopped, checked this often.
constexpr TimePs kStopCheckPs = 10 * kPsPerMs;

// Every wire of the system: the machine pins named as in every architecture, then the link (README "Pins"; VCD
// and analyze scripts rely on the names).
struct Wires {
    sc_core::sc_signal<bool> step_x{"step_x", false}, dir_x{"dir_x", false};
    sc_core::sc_signal<bool> step_y{"step_y", false}, dir_y{"dir_y", false};
    sc_core::sc_signal<bool> n_enbl_x{"n_enbl_x", false}, n_enbl_y{"n_enbl_y", false};
    sc_core::sc_signal<bool> laser{"laser", false};  // PB1, the HEADER bit of the start byte
    sc_core::sc_signal<bool> uart_rx{"uart_rx", true};  // CP2102 TXD -> PD0 RXD; idles high
    sc_core::sc_signal<bool> uart_tx{"uart_tx", true};  // PD1 TXD -> CP2102 RXD

    [[nodiscard]] std::array<const sc_core::sc_signal<bool>*, 9> all() const {
        return {&step_x, &dir_x, &step_y, &dir_y, &n_enbl_x, &n_enbl_y, &laser, &uart_rx, &uart_tx};
    }
};

// The VCD's pins, each with the clock that times its edges: the AVR's for every pin it drives; the CP2102
// (uart_rx) starts its frames when USB delivers the bytes.
std::vector<TracedPin> traced_pins(const Wires& w, std::int64_t avr_clock_hz) {
    std::vector<TracedPin> pins;
    for (const sc_core::sc_signal<bool>* sig : w.all()) {
        pins.push_back({sig, sig == &w.uart_rx ? std::nullopt : std::optional<std::int64_t>(avr_clock_hz)});
    }
    return pins;
}

std::string firmware_path(const Scenario& s) {
    if (!s.atmega.firmware.empty()) return s.atmega.firmware;
    return s.atmega.g01_timer2_prescaler == 256 ? CNC_SEED003_T2CS110_ELF : CNC_SEED003_ELF;
}

avr::AvrCoreConfig avr_config(const Scenario& s) {
    avr::AvrCoreConfig cfg;
    cfg.firmware_elf = firmware_path(s);
    cfg.pins = avr::parse_pin_map(s.atmega.pins, s.file + ": avr.pins");
    cfg.where = s.file + ": avr.firmware";
    cfg.quantum_cycles = s.atmega.quantum_cycles;
    return cfg;
}

uart::Cp2102Config link_config(const Scenario& s) {
    uart::Cp2102Config link = s.link;
    if (!s.atmega.link_baud_set) link.requested_baud = s3::kSeedBaud;  // seed 003 §3.4: CBR_57600
    return link;
}

// The metrics' move of a motion that ran, its window from the PORTB pins. A G00 runs each axis at v_max on its
// own (the seed's dog-leg), so its commanded per-axis rates are v_max, not the path feed split.
metrics::MoveSpec executed_move(const Scenario& s, metrics::MoveSpec m, const MotionWindow& window) {
    m.t_begin_ps = window.t_begin_ps;
    m.t_end_ps = window.t_end_ps;
    if (m.rapid) {
        const double v_mm_per_s = m.feed_mm_per_min / 60.0;
        m.rate_steps_per_s = {m.steps[0] != 0 ? v_mm_per_s * s.machine.x.steps_per_mm() : 0.0,
                              m.steps[1] != 0 ? v_mm_per_s * s.machine.y.steps_per_mm() : 0.0};
    }
    return m;
}

// The programmed move of each transfer; M30 belongs to none (the waits after the last move come before it).
std::vector<std::size_t> transfer_moves(const s3::Plan& plan, const std::vector<s3::Transfer>& transfers,
                                        std::size_t n_moves) {
    std::vector<std::size_t> out;
    for (const s3::Transfer& t : transfers) {
        const std::vector<s3::Motion>& motions = plan.commands[t.command].motions;
        out.push_back(motions.empty() ? n_moves : static_cast<std::size_t>(motions.front().move));
    }
    return out;
}

// The atmega side of the job estimate. An axis steps at most at OCR = 0, f / 2N (48.8 mm/s at 160 steps/mm):
// a faster feed runs at that rate. (The truncated OCR otherwise only makes moves faster: OCR + 1 <= f / (2 N
// v/s).) CAD2G settles, then writes every byte after the confirm of the one before: per byte the write latency,
// a USB frame out, the byte and its confirm on the line, a frame in and the driver latency; per transfer the
// PC's work. The chords of an arc overlap the previous chord's motion, so this counts them twice: an upper bound.
ArchPace pace(const Scenario& s, const uart::Cp2102Config& link, const std::vector<s3::Transfer>& transfers) {
    ArchPace p;
    // The PC program also holds every speed to the machine's velocity limits.
    p.max_speed_x_mm_per_s = std::min(s3::speed_mm_per_s(0, s.machine.x.mm_per_step(), s.atmega.pc.timer),
                                      s.machine.x.limits.max_velocity_mm_per_s);
    p.max_speed_y_mm_per_s = std::min(s3::speed_mm_per_s(0, s.machine.y.mm_per_step(), s.atmega.pc.timer),
                                      s.machine.y.limits.max_velocity_mm_per_s);
    p.startup_s = ps_to_s(s.sender.settle_ps);
    const double byte_s = ps_to_s(host::byte_round_trip_ps(s.sender, link));
    for (const s3::Transfer& t : transfers) {
        p.link_s += ps_to_s(s.sender.packet_processing_ps) + static_cast<double>(t.bytes.size()) * byte_s;
    }
    return p;
}

// The firmware's USART against the CP2102's rate, before anything is simulated (systems/link_checks.hpp).
void check_firmware_rate(const Scenario& s, const uart::Cp2102Config& link, const avr::AvrCoreConfig& avr_cfg) {
    const std::optional<FirmwareUsart> usart = probe_firmware_usart(avr_cfg);
    if (!usart) return;
    const std::string firmware =
        s.atmega.firmware.empty() ? "the seed 003 firmware" : "the firmware " + avr_cfg.firmware_elf;
    check_line_rates(s.file + ": link.baud, avr.firmware", cp2102_end(link),
                     {usart->baud, firmware + "'s USART0 at " + usart->text(avr_cfg.f_cpu_hz)});
}

host::ConfirmTimeouts confirm_timeouts(const Scenario& s, const uart::Cp2102Config& link, const s3::Plan& plan,
                                       const std::vector<s3::Transfer>& transfers) {
    host::ConfirmTimeouts t;
    t.round_trip_ps = host::byte_round_trip_ps(s.sender, link);
    for (const double busy_s : s3::motion_before_next_confirm_s(plan, transfers, s.atmega.pc.timer)) {
        t.motion_after_ps.push_back(s_to_ps(busy_s));
    }
    return t;
}

// Why the link does not work, once it is clear: frames garbled at either end, or the PC program's protocol check
// (which names the firmware it checked).
std::optional<std::string> link_failure(const avr::AvrCore& mcu, const uart::Cp2102& cp2102,
                                        const host::PcProgram& pc) {
    if (auto framing = framing_failure(mcu.stats().usart.rx_framing_errors, "MCU", cp2102.stats().framing_errors)) {
        return framing;
    }
    if (pc.failure()) return pc.failure()->reason + " (avr.firmware " + mcu.config().firmware_elf + ")";
    return std::nullopt;
}

}  // namespace

ArchRun run_atmega(const Scenario& s, const Job& job) {
    if (!job.program) {
        throw BadInput(s.file + ": scenario.job",
                       "a steps file is seed 000's format, run only by fpga-uart; the atmega PC program reads G-code");
    }
    const s3::Plan plan = s3::plan_program(*job.program, s.machine, s.atmega.pc);
    const avr::AvrCoreConfig avr_cfg = avr_config(s);

    const uart::Cp2102Config link = link_config(s);
    check_firmware_rate(s, link, avr_cfg);
    const std::vector<s3::Transfer> transfers = s3::transfers(plan);

    Wires w;
    uart::Cp2102 cp2102("cp2102", link);
    cp2102.txd(w.uart_rx);
    cp2102.rxd(w.uart_tx);
    host::PcProgram pc("host", s.sender, cp2102, transfers, confirm_timeouts(s, link, plan, transfers));
    pc.set_waits(host::waits_per_unit(*job.program, transfer_moves(plan, transfers, job.program->moves.size())));
    avr::AvrCore mcu("atmega328p", avr_cfg);
    mcu.step_x(w.step_x);
    mcu.dir_x(w.dir_x);
    mcu.en_x(w.n_enbl_x);
    mcu.step_y(w.step_y);
    mcu.dir_y(w.dir_y);
    mcu.en_y(w.n_enbl_y);
    mcu.head(w.laser);
    mcu.txd(w.uart_tx);
    mcu.rxd(w.uart_rx);
    mech::Drv8825Config driver = s.driver;
    driver.dir_high_is_positive = false;  // seed 003 §2.2: DIR 0 = CW = +X / +Y
    Machine machine("machine", s.machine, driver, s.interpreter.start_mm, s.mechanics, !s.vcd_path.empty());
    machine.bind(w.step_x, w.dir_x, w.n_enbl_x, w.step_y, w.dir_y, w.n_enbl_y, w.laser);
    EdgeRecorder rec("probes");
    for (const sc_core::sc_signal<bool>* sig : {&w.step_x, &w.dir_x, &w.step_y, &w.dir_y, &w.n_enbl_x, &w.n_enbl_y,
                                                &w.laser}) {
        rec.watch(*sig, sig->basename());
    }
    if (s.keep_run_input) {  // the link's lines: only the tests read them
        for (const sc_core::sc_signal<bool>* sig : {&w.uart_rx, &w.uart_tx}) rec.watch(*sig, sig->basename());
    }
    std::unique_ptr<VcdTrace> vcd;
    if (!s.vcd_path.empty()) {
        vcd = std::make_unique<VcdTrace>(s, traced_pins(w, avr_cfg.f_cpu_hz), machine.traced_positions());
    }

    const RunBudget budget = run_budget(s, estimate_job(*job.program, pace(s, link, transfers)));
    // The pins are read slice by slice and the metrics stream (their inputs dropped as they are measured), unless
    // the whole logs are asked for: then they are read once, at the end, for the batch metrics.
    AtmegaPins pins(rec, plan, s.keep_run_input);
    const std::vector<metrics::MoveSpec> commanded =
        commanded_moves(&*job.program, s3::motion_segments(plan, s.machine), s.machine, s.interpreter.start_mm);
    std::optional<MetricsFeed> feed;
    if (!s.keep_run_input) {
        const std::vector<AxisPins> axes{{"x", "step_x", "dir_x", s.machine.x.steps_per_mm(), false},
                                         {"y", "step_y", "dir_y", s.machine.y.steps_per_mm(), false}};
        feed_on_carriage(feed, rec, axes, machine, s.detail);
        // Every fold comes right after the pins were read up to its instant: the edges before it are all there.
        feed->take_edges_with([&pins](const std::string& pin, TimePs t_ps) { return pins.hand_over(pin, t_ps); });
    }
    // The late chords are folded as the bytes and the windows come, so that neither is kept for the whole run.
    ChordGapFold chord_gaps(pc.transfers());
    const auto read_link = [&] {
        read_link_bytes(pc, cp2102, uart::decision_offset_ps(mcu.chip().rx_clock(), mcu.chip().rx_format()),
                        [&](std::size_t transfer, TimePs t_ps) { chord_gaps.add_byte(transfer, t_ps); });
    };
    std::size_t handed = 0;  // motion windows handed to the metrics
    const auto hand_ended_moves = [&] {
        for (; handed < pins.windows().size(); ++handed) {
            feed->add_piece(executed_move(s, commanded[handed], pins.windows()[handed]));
        }
    };
    SimulationEnd end = simulate(
        budget, [&] { return mcu.stopped() || link_failure(mcu, cp2102, pc).has_value(); }, kStopCheckPs,
        [&](TimePs now_ps) {
            read_link();
            if (!feed) return;
            pins.read_before(now_ps);
            chord_gaps.add_windows(pins.windows(), false);
            hand_ended_moves();
            if (!s.detail) pins.drop_windows_before(std::min(handed, chord_gaps.next_window()));  // --detail lists them
            feed->fold(now_ps);
        });
    const TimePs t_now = end.t_ps;
    if (vcd) vcd->close();
    machine.finish_mechanics(end, budget.limit_ps, true);

    ArchRun run;
    record_budget(budget, run);
    pins.read_before(std::numeric_limits<TimePs>::max());
    pins.finish(t_now);
    read_link();
    chord_gaps.add_windows(pins.windows(), true);
    metrics::RunInput& in = run.input;
    in.t_job_start_ps = 0;
    in.t_job_end_ps = mcu.chip().stop_cycle() ? mcu.cycle_ps(*mcu.chip().stop_cycle()) : t_now;
    if (feed) {
        hand_ended_moves();
        run.metrics = feed->finish(in.t_job_end_ps);
    } else {
        in.axes.push_back({"x", pins.hand_over("step_x"), pins.hand_over("dir_x"), s.machine.x.steps_per_mm(), false});
        in.axes.push_back({"y", pins.hand_over("step_y"), pins.hand_over("dir_y"), s.machine.y.steps_per_mm(), false});
        for (std::size_t i = 0; i < pins.windows().size(); ++i) {
            in.moves.push_back(executed_move(s, commanded[i], pins.windows()[i]));
        }
        in.tool = machine.carriage().samples();
        in.laser = pins.hand_over("laser");
        for (const char* pin : {"uart_rx", "uart_tx"}) run.lines[pin] = rec.take(pin);
        for (const char* pin : {"n_enbl_x", "n_enbl_y"}) run.lines[pin] = pins.take_raw(pin);
        run.lines["step_x_pin"] = pins.take_raw("step_x");  // the raw pins: the timers toggle them while EN is high too
        run.lines["step_y_pin"] = pins.take_raw("step_y");
    }

    run.warnings = plan.warnings;
    const AtmegaFacts facts{plan, s.machine, pc, cp2102, mcu, pins.windows(), chord_gaps.gaps(), avr_cfg.firmware_elf,
                            mcu.chip().rx_clock().baud()};
    for (Warning& w : link_warnings(facts)) run.warnings.push_back(std::move(w));
    run.details = details_json(facts, s.detail);
    run.details_text = details_text(facts);
    add_mechanics_report(machine, feed, run);

    if (const std::optional<std::string> why = link_failure(mcu, cp2102, pc)) {
        run.ok = false;
        run.failure = *why + format(" (run stopped at %.3f s of simulated time)", ps_to_s(t_now));
    } else if (!pc.finished()) {
        run.ok = false;
        run.failure = mcu.stopped() ? "the firmware stopped before the PC program had sent the job"
                                    : "the job did not finish: " + time_limit_text(budget, end);
    } else if (!mcu.stopped()) {
        run.ok = false;
        run.failure = "the firmware did not reach M30: " + time_limit_text(budget, end);
    }
    return run;
}

}  // namespace cnc::sim
