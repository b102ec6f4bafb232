#include "architectures/atmega/atmega.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/atmega/atmega_pins.hpp"
#include "architectures/atmega/atmega_report.hpp"
#include "architectures/atmega/atmega_settings.hpp"
#include "architectures/atmega/chord_gaps.hpp"
#include "architectures/atmega/link_bytes.hpp"
#include "architectures/avr_board/avr_board.hpp"
#include "architectures/avr_board/board_faults.hpp"
#include "architectures/avr_board/board_link_report.hpp"
#include "architectures/avr_board/board_wiring.hpp"
#include "architectures/serial_host/host_faults.hpp"
#include "avr/avr_core.hpp"
#include "common/bad_input.hpp"
#include "host/core/cad2g/firmware_busy.hpp"
#include "host/pc_program.hpp"
#include "run/controller.hpp"
#include "run/machine_run.hpp"
#include "run/moves.hpp"
#include "run/windowed_moves.hpp"
#include "uart/core/line_receiver.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim::atmega {

namespace {

namespace cad2g = host::cad2g;

// The chip's timers run on after M30 (cli; sleep): the run ends when the firmware has stopped, checked this often.
constexpr TimePs kStopCheckPs = 10 * kPsPerMs;

std::string firmware_path(const AtmegaSettings& a) {
    if (!a.board.firmware.empty()) return a.board.firmware;
    if (a.pc.variant == cad2g::Variant::Timer1Y) return CNC_LASER_ENGRAVER_TIMER1_Y_ELF;
    return a.g01_timer2_prescaler == 256 ? CNC_LASER_ENGRAVER_T2CS110_ELF : CNC_LASER_ENGRAVER_ELF;
}

avr::AvrCoreConfig avr_config(const Scenario& s, const AtmegaSettings& a) {
    return board_config(s, a.board, firmware_path(a),
                        a.pc.variant == cad2g::Variant::Timer1Y ? avr::timer1_y_pin_map() : avr::default_pin_map());
}

uart::Cp2102Config link_config(const AtmegaSettings& a) {
    uart::Cp2102Config link = a.serial.link;
    if (!a.link_baud_set) link.requested_baud = cad2g::kSeedBaud;  // seed 003 §5.3.2: CBR_57600
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
std::vector<std::size_t> transfer_moves(const cad2g::Plan& plan, const std::vector<cad2g::Transfer>& transfers,
                                        std::size_t n_moves) {
    std::vector<std::size_t> out;
    for (const cad2g::Transfer& t : transfers) {
        const std::vector<cad2g::Motion>& motions = plan.commands[t.command].motions;
        out.push_back(motions.empty() ? n_moves : static_cast<std::size_t>(motions.front().move));
    }
    return out;
}

// This architecture's side of the job estimate. An axis steps at most at OCR = 0, f / 2N (48.8 mm/s at 160 steps/mm):
// a faster feed runs at that rate. (The truncated OCR otherwise only makes moves faster: OCR + 1 <= f / (2 N
// v/s); a rounded one, avr.variant, at most 4/3 slower, at an exact OCR of 0.5, within the limit's factor of 2.)
// CAD2G settles, then writes every byte after the confirm of the one before: per byte the write latency,
// a USB frame out, the byte and its confirm on the line, a frame in and the driver latency; per transfer the
// PC's work. The chords of an arc overlap the previous chord's motion, so this counts them twice: an upper bound.
ArchPace pace(const Scenario& s, const AtmegaSettings& a, const uart::Cp2102Config& link,
              const std::vector<cad2g::Transfer>& transfers) {
    ArchPace p;
    // The PC program also holds every speed to the machine's velocity limits.
    p.max_speed_x_mm_per_s = std::min(cad2g::speed_mm_per_s(0, s.machine.x.mm_per_step(), a.pc.timer),
                                      s.machine.x.limits.max_velocity_mm_per_s);
    p.max_speed_y_mm_per_s =
        std::min(cad2g::speed_mm_per_s(0, s.machine.y.mm_per_step(), cad2g::y_timer(a.pc.variant, a.pc.timer)),
                 s.machine.y.limits.max_velocity_mm_per_s);
    p.startup_s = ps_to_s(a.serial.sender.settle_ps);
    const double byte_s = ps_to_s(host::byte_round_trip_ps(a.serial.sender, link));
    for (const cad2g::Transfer& t : transfers) {
        p.link_s += ps_to_s(a.serial.sender.packet_processing_ps) + static_cast<double>(t.bytes.size()) * byte_s;
    }
    return p;
}

host::ConfirmTimeouts confirm_timeouts(const AtmegaSettings& a, const uart::Cp2102Config& link, const cad2g::Plan& plan,
                                       const std::vector<cad2g::Transfer>& transfers) {
    host::ConfirmTimeouts t;
    t.round_trip_ps = host::byte_round_trip_ps(a.serial.sender, link);
    for (const double busy_s : cad2g::motion_before_next_confirm_s(plan, transfers)) {
        t.motion_after_ps.push_back(s_to_ps(busy_s));
    }
    return t;
}

// The PC program as the scenario sets it, with the host stall of its faults.
host::SenderConfig pc_config(const Scenario& s, const AtmegaSettings& a) {
    host::SenderConfig c = a.serial.sender;
    c.stall = stall_window(s.faults.host_stall);
    return c;
}

// The seed 003 system between the job and the machine's pins: the PC program (CAD2G) through the CP2102, the
// ATmega328P running its firmware, which drives STEP, DIR, EN and the head.
class AtmegaController final : public Controller {
public:
    // `plan`, `avr_cfg`, `link`: checked_plan().
    AtmegaController(const Scenario& s, const Job& job, MachinePins& pins, cad2g::Plan plan, avr::AvrCoreConfig avr_cfg,
                     uart::Cp2102Config link, const std::optional<FirmwareUsart>& usart)
        : m_s(s),
          m_a(s.settings<AtmegaSettings>()),
          m_job(job),
          m_plan(std::move(plan)),
          m_avr_cfg(std::move(avr_cfg)),
          m_link(link),
          m_transfers(cad2g::transfers(m_plan)),
          m_cp2102("cp2102", m_link),
          m_pc("host", pc_config(s, m_a), m_cp2102, m_transfers, confirm_timeouts(m_a, m_link, m_plan, m_transfers)),
          m_mcu(m_avr_cfg.mcu.c_str(), m_avr_cfg),
          m_moves(commanded_moves(&*job.program, cad2g::motion_segments(m_plan, s.machine), s.machine,
                                  s.interpreter.start_mm)),
          m_chord_gaps(m_pc.transfers()),
          m_faults(board_line_faults(s.faults, m_cp2102, usart, m_avr_cfg.f_cpu_hz)) {
        m_pc.set_waits(
            host::waits_per_unit(*job.program, transfer_moves(m_plan, m_transfers, job.program->moves.size())));
        wire_board(m_wires, m_cp2102, m_mcu, pins,
                   m_faults.get());  // the head: the HEADER bit of the start byte, PB1 (timer1-y: PB3)
    }

    [[nodiscard]] MachinePinClocks pin_clocks() const override { return board_pin_clocks(m_mcu); }
    [[nodiscard]] std::vector<TracedPin> traced_pins() const override { return board_traced_pins(m_wires, m_mcu); }
    // Seed 003 §5.2.5: DIR 0 = CW = +X / +Y.
    [[nodiscard]] bool dir_high_is_positive() const override { return false; }
    // The firmware switches each driver off once its axis has counted its steps (seed 003 App. A2, A4).
    [[nodiscard]] bool drives_enable() const override { return true; }
    // The pins are read slice by slice as the metrics stream; with the whole logs kept, once, at the end. The link's
    // lines only then: only the tests read them.
    void record(EdgeRecorder& rec, bool whole_logs) override {
        m_whole_logs = whole_logs;
        m_pins.emplace(rec, m_plan, whole_logs);
        if (whole_logs) watch_board_lines(rec, m_wires);
    }

    [[nodiscard]] JobEstimate estimate() const override {
        return estimate_job(*m_job.program, pace(m_s, m_a, m_link, m_transfers));
    }
    [[nodiscard]] TimePs stop_check_ps() const override { return kStopCheckPs; }
    [[nodiscard]] bool stopped() override { return m_mcu.stopped() || link_failure().has_value(); }
    // Every fold comes right after the pins were read up to its instant: the edges before it are all there.
    void feed_started(MetricsFeed& feed) override {
        feed.take_edges_with([this](const std::string& pin, TimePs t_ps) { return m_pins->hand_over(pin, t_ps); });
    }
    // The late chords are folded as the bytes and the windows come, so that neither is kept for the whole run.
    void slice_ended(TimePs now_ps, MetricsFeed* feed) override {
        read_link();
        if (feed == nullptr) return;
        m_pins->read_before(now_ps);
        m_chord_gaps.add_windows(m_pins->windows(), false);
        hand_ended_moves(*feed);
        if (!m_s.detail)
            m_pins->drop_windows_before(std::min(m_moves.next_window(), m_chord_gaps.next_window()));  // --detail
        feed->fold(now_ps);
    }

    void simulation_ended(TimePs stop_ps) override {
        m_stop_ps = stop_ps;
        m_pins->read_before(std::numeric_limits<TimePs>::max());
        m_pins->finish(stop_ps);
        read_link();
        m_chord_gaps.add_windows(m_pins->windows(), true);
    }
    [[nodiscard]] TimePs job_end_ps(TimePs stop_ps) const override {
        return m_mcu.chip().stop_cycle() ? m_mcu.cycle_ps(*m_mcu.chip().stop_cycle()) : stop_ps;
    }
    void finish_feed(MetricsFeed& feed) override {
        hand_ended_moves([&](metrics::MoveSpec m) { feed.add_piece(std::move(m)); }, true);
    }
    void finish_input(metrics::RunInput& in, bool streamed) override {
        if (streamed) return;
        hand_ended_moves([&](metrics::MoveSpec m) { in.moves.push_back(std::move(m)); }, true);
    }
    // The STEP pulses the drivers act on (nENBL low), and the DIR and laser edges.
    [[nodiscard]] EdgeLog take_edges(EdgeRecorder&, const std::string& pin) override { return m_pins->hand_over(pin); }
    void take_lines(EdgeRecorder& rec, std::map<std::string, EdgeLog>& lines) override {
        if (m_whole_logs) take_board_lines(rec, m_pins->driven(), lines);
    }
    void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) override;

private:
    void report_faults(ArchRun& run) const;
    // Why the link does not work, once it is clear; the PC program's protocol check names the firmware it checked.
    [[nodiscard]] std::optional<std::string> link_failure() const {
        return board_link_failure(m_mcu, m_cp2102,
                                  m_pc.failure() ? std::optional(m_pc.failure()->reason) : std::nullopt,
                                  m_faults != nullptr);
    }
    void read_link() {
        if (m_faults) m_faults->take_host_bytes(m_cp2102, [this](std::size_t j) { return m_pc.writes()[j].transfer; });
        read_link_bytes(m_pc, m_cp2102, uart::decision_offset_ps(m_mcu.chip().rx_clock(), m_mcu.chip().rx_format()),
                        [&](std::size_t transfer, TimePs t_ps) { m_chord_gaps.add_byte(transfer, t_ps); });
    }
    template <typename F>
    void hand_ended_moves(F f, bool final) {
        m_moves.hand(
            m_pins->windows(), [this](metrics::MoveSpec m, const MotionWindow& w) { return executed_move(m_s, m, w); },
            f, final);
    }
    void hand_ended_moves(MetricsFeed& feed) {
        hand_ended_moves([&](metrics::MoveSpec m) { feed.add_piece(std::move(m)); }, false);
    }

    const Scenario& m_s;
    const AtmegaSettings& m_a;
    const Job& m_job;
    const cad2g::Plan m_plan;
    const avr::AvrCoreConfig m_avr_cfg;
    const uart::Cp2102Config m_link;
    const std::vector<cad2g::Transfer> m_transfers;
    BoardWires m_wires;
    uart::Cp2102 m_cp2102;
    host::PcProgram m_pc;
    avr::AvrCore m_mcu;
    WindowedMoves m_moves;
    std::optional<AtmegaPins> m_pins;  // once the recorder watches the pins
    ChordGapFold m_chord_gaps;
    std::unique_ptr<BoardLineFaults> m_faults;  // with faults on the link's wires
    TimePs m_stop_ps = 0;
    bool m_whole_logs = false;
};

// The seed's protocol has no check: a transfer with a byte that did not arrive as sent either runs as the firmware
// read it, once its confirm lets the PC program go on to the next transfer, or stops the program (no confirm, or a
// byte other than the confirm).
void AtmegaController::report_faults(ArchRun& run) const {
    const BoardLineFaultResult r = m_faults->result(m_mcu);
    const std::vector<std::size_t> hit = m_faults->units_hit(r.to_mcu);
    const std::optional<std::size_t> last = m_faults->last_unit_sent();
    std::size_t ran_on = 0;
    for (const std::size_t t : hit) {
        if (t < *last || m_pc.finished()) ++ran_on;
    }
    nlohmann::json j = board_faults_json(m_s.faults, r);
    j["transfers"] = {{"sent", last ? *last + 1 : 0},
                      {"hit", hit.size()},
                      {"ran_without_a_check_noticing", ran_on},
                      {"stopped_the_pc_program", hit.size() - ran_on}};
    j["commands_run_changed"] = ran_on;
    run.details["faults"] = std::move(j);
    run.details_text +=
        board_faults_text(m_s.faults, r) +
        fmt::format(FMT_STRING("  transfers: {} with a byte that did not arrive as sent, {} of them run "
                               "without a check noticing\n"),
                    hit.size(), ran_on);
}

void AtmegaController::report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) {
    run.warnings = m_plan.warnings;
    const AtmegaFacts facts{m_plan,
                            m_s.machine,
                            m_pc,
                            m_cp2102,
                            m_mcu,
                            m_pins->windows(),
                            m_chord_gaps.gaps(),
                            m_avr_cfg.firmware_elf,
                            m_mcu.chip().rx_clock().baud()};
    for (Warning& w : link_warnings(facts)) run.warnings.push_back(std::move(w));
    run.details = details_json(facts, m_s.detail);
    run.details_text = details_text(facts);
    run.clock = oscillator_json(m_a.board.clock, m_mcu.chip().clock());
    run.clock_text = oscillator_text(m_a.board.clock, m_mcu.chip().clock());

    if (m_faults) report_faults(run);
    report_usb_spikes(m_s.faults, m_cp2102, run);
    report_host_stall(m_s.faults.host_stall, m_pc.stalled_ps(), run);
    if (const std::optional<std::string> why = link_failure()) {
        run.ok = false;
        run.failure = stopped_at(*why, m_stop_ps);
    } else if (!m_pc.finished()) {
        run.ok = false;
        run.failure = m_mcu.stopped() ? "the firmware stopped before the PC program had sent the job"
                                      : "the job did not finish: " + time_limit_text(budget, end);
    } else if (!m_mcu.stopped()) {
        run.ok = false;
        run.failure = "the firmware did not reach M30: " + time_limit_text(budget, end);
    }
}

}  // namespace

ArchRun Entry::run(const Scenario& s, const Job& job) {
    return run_on_machine(s, job, [](const Scenario& sc, const Job& j, MachinePins& pins) {
        const AtmegaSettings& a = sc.settings<AtmegaSettings>();
        cad2g::Plan plan = cad2g::plan_program(*j.program, sc.machine, a.pc);
        avr::AvrCoreConfig avr_cfg = avr_config(sc, a);
        const uart::Cp2102Config link = with_usb_spikes(link_config(a), sc.faults);
        avr_cfg.keep_usart_logs = sc.faults.uart.any();  // board_faults.hpp matches every byte
        const std::optional<FirmwareUsart> usart = check_firmware_rate(
            sc, link, avr_cfg,
            a.board.firmware.empty() ? "the seed 003 firmware" : "the firmware " + avr_cfg.firmware_elf);
        return std::make_unique<AtmegaController>(sc, j, pins, std::move(plan), std::move(avr_cfg), link, usart);
    });
}

}  // namespace cnc::sim::atmega
