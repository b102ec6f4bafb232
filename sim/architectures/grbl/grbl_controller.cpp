#include "architectures/grbl/grbl.hpp"

#include <array>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "architectures/avr_board/avr_board.hpp"
#include "architectures/avr_board/board_faults.hpp"
#include "architectures/avr_board/board_link_report.hpp"
#include "architectures/avr_board/board_wiring.hpp"
#include "architectures/avr_board/driven_pins.hpp"
#include "architectures/grbl/grbl_report.hpp"
#include "architectures/grbl/grbl_settings.hpp"
#include "architectures/grbl/step_windows.hpp"
#include "architectures/serial_host/host_faults.hpp"
#include "avr/avr_core.hpp"
#include "common/bad_input.hpp"
#include "host/core/cam.hpp"
#include "host/core/grbl/grbl_lines.hpp"
#include "host/core/grbl/grbl_settings.hpp"
#include "host/grbl_sender.hpp"
#include "run/controller.hpp"
#include "run/machine_run.hpp"
#include "run/moves.hpp"
#include "run/windowed_moves.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim::grbl {

namespace {

// The sender's end and a failure are checked this often.
constexpr TimePs kStopCheckPs = 10 * kPsPerMs;

// The job file's lines as the sender streams them.
std::vector<host::grbl::SendLine> job_lines(const Scenario& s) {
    std::ifstream in(s.job_path, std::ios::binary);
    if (!in) throw BadInput(s.job_key, "cannot read the job " + s.job_path);
    std::ostringstream text;
    text << in.rdbuf();
    return host::grbl::lines_to_send(text.str(), s.job_path);
}

// grbl's laser mode ($32 = 1) for a job that switches a laser: M3/M4 with a power on a cutting move.
bool laser_job(const host::Program& program) {
    for (const host::ProgrammedMove& m : program.moves) {
        if (m.laser_intended()) return true;
    }
    return false;
}

host::grbl::Stream make_stream(const Scenario& s, const GrblSettings& g, const Job& job) {
    return host::grbl::Stream(
        {g.protocol, g.rx_buffer_bytes, s.interpreter.policy == host::GcodePolicy::Strict},
        host::grbl::machine_settings(s.machine, laser_job(*job.program), g.settings, g.settings_where, s.file),
        job_lines(s));
}

// The sender as the scenario sets it, with the host stall of its faults.
host::GrblSenderConfig sender_config(const Scenario& s, const GrblSettings& g) {
    host::GrblSenderConfig c;
    c.stall = stall_window(s.faults.host_stall);
    c.processing_ps = g.serial.sender.packet_processing_ps;
    c.write_latency_ps = g.serial.sender.write_latency_ps;
    c.status_interval_ps = g.status_interval_ps;
    return c;
}

// Each stepped move's end point on the step grid, counted from the start.
std::vector<std::array<std::int64_t, 2>> move_ends(const std::vector<host::MotionSegment>& segments) {
    std::vector<std::array<std::int64_t, 2>> ends;
    std::array<std::int64_t, 2> at{};
    for (const host::MotionSegment& seg : segments) {
        at[0] += seg.steps_x;
        at[1] += seg.steps_y;
        ends.push_back(at);
    }
    return ends;
}

// The metrics' move of a block that ran, its window from the pins. grbl runs a G0 at the fastest speed every axis
// allows ($110/$111: the machine's limits), not at the job's rapid feed.
metrics::MoveSpec executed_move(const Scenario& s, metrics::MoveSpec m, const StepWindow& window) {
    m.t_begin_ps = window.t_begin_ps;
    m.t_end_ps = window.t_end_ps;
    if (m.rapid) {
        const geom::Vec2 d_mm = m.to_mm - m.from_mm;
        set_path_feed(
            m, host::feed_within_axis_limits(d_mm.x_mm, d_mm.y_mm, std::numeric_limits<double>::max(), s.machine));
    }
    return m;
}

// This architecture's side of the job estimate: each axis at its limit; every line's bytes on the wire and the
// sender's work, as if nothing overlapped them.
ArchPace pace(const Scenario& s, const GrblSettings& g, const uart::Cp2102Config& link,
              const std::vector<host::grbl::SendLine>& lines) {
    ArchPace p;
    p.max_speed_x_mm_per_s = s.machine.x.limits.max_velocity_mm_per_s;
    p.max_speed_y_mm_per_s = s.machine.y.limits.max_velocity_mm_per_s;
    const double byte_s = static_cast<double>(link.format.bits_per_frame()) / link.requested_baud;
    for (const host::grbl::SendLine& l : lines) {
        p.link_s += ps_to_s(g.serial.sender.packet_processing_ps + g.serial.sender.write_latency_ps) +
                    static_cast<double>(l.text.size() + 1) * byte_s;
    }
    return p;
}

// The grbl system between the job and the machine's pins: the G-code sender through the CP2102, the ATmega328P
// running the user's firmware, which drives STEP, DIR, the shared enable and the laser.
class GrblController final : public Controller {
public:
    GrblController(const Scenario& s, const Job& job, MachinePins& pins, avr::AvrCoreConfig avr_cfg,
                   std::vector<host::MotionSegment> segments, const std::optional<FirmwareUsart>& usart)
        : m_s(s),
          m_g(s.settings<GrblSettings>()),
          m_job(job),
          m_avr_cfg(std::move(avr_cfg)),
          m_ends(move_ends(segments)),
          m_cp2102("cp2102", with_usb_spikes(m_g.serial.link, s.faults)),
          m_sender("host", sender_config(s, m_g), m_cp2102, make_stream(s, m_g, job)),
          m_mcu(m_avr_cfg.mcu.c_str(), m_avr_cfg),
          m_moves(commanded_moves(&*job.program, segments, s.machine, s.interpreter.start_mm)),
          m_faults(board_line_faults(s.faults, m_cp2102, usart, m_avr_cfg.f_cpu_hz)) {
        wire_board(m_wires, m_cp2102, m_mcu, pins, m_faults.get());
    }

    [[nodiscard]] MachinePinClocks pin_clocks() const override { return board_pin_clocks(m_mcu); }
    [[nodiscard]] std::vector<TracedPin> traced_pins() const override { return board_traced_pins(m_wires, m_mcu); }
    // grbl 1.1: a DIR bit set moves its axis the negative way ($3 = 0).
    [[nodiscard]] bool dir_high_is_positive() const override { return false; }
    // grbl holds its stepper-disable pin high until the first block and after an idle delay ($1).
    [[nodiscard]] bool drives_enable() const override { return true; }
    void record(EdgeRecorder& rec, bool whole_logs) override {
        m_whole_logs = whole_logs;
        m_pins.emplace(rec, whole_logs);
        m_windows.emplace(m_ends, dir_high_is_positive());
        if (whole_logs) watch_board_lines(rec, m_wires);
    }

    [[nodiscard]] JobEstimate estimate() const override {
        return estimate_job(*m_job.program, pace(m_s, m_g, m_g.serial.link, m_sender.stream().job()));
    }
    [[nodiscard]] TimePs stop_check_ps() const override { return kStopCheckPs; }
    [[nodiscard]] bool stopped() override {
        return m_sender.finished() ||
               board_link_failure(m_mcu, m_cp2102, m_sender.failure(), m_faults != nullptr).has_value();
    }
    void feed_started(MetricsFeed& feed) override {
        feed.take_edges_with([this](const std::string& pin, TimePs t_ps) { return m_pins->hand_over(pin, t_ps); });
    }
    void slice_ended(TimePs now_ps, MetricsFeed* feed) override {
        if (feed == nullptr) return;
        read_before(now_ps);
        hand_ended_moves([&](metrics::MoveSpec m) { feed->add_piece(std::move(m)); }, false);
        if (!m_s.detail) m_windows->drop_windows_before(m_moves.next_window());
        feed->fold(now_ps);
    }
    void simulation_ended(TimePs stop_ps) override {
        read_before(std::numeric_limits<TimePs>::max());
        m_windows->finish(stop_ps);
    }
    [[nodiscard]] TimePs job_end_ps(TimePs stop_ps) const override {
        return m_sender.finished() ? m_sender.t_end_ps() : stop_ps;
    }
    void finish_feed(MetricsFeed& feed) override {
        hand_ended_moves([&](metrics::MoveSpec m) { feed.add_piece(std::move(m)); }, true);
    }
    void finish_input(metrics::RunInput& in, bool streamed) override {
        if (streamed) return;
        hand_ended_moves([&](metrics::MoveSpec m) { in.moves.push_back(std::move(m)); }, true);
    }
    [[nodiscard]] EdgeLog take_edges(EdgeRecorder&, const std::string& pin) override { return m_pins->hand_over(pin); }
    void take_lines(EdgeRecorder& rec, std::map<std::string, EdgeLog>& lines) override {
        if (m_whole_logs) take_board_lines(rec, *m_pins, lines);
    }
    void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) override;

private:
    void read_before(TimePs t_ps) {
        const PinSlice p = m_pins->read_before(t_ps);
        m_windows->add(p.step_x, p.dir_x, p.step_y, p.dir_y);
    }
    template <typename F>
    void hand_ended_moves(F f, bool final) {
        m_moves.hand(
            m_windows->windows(), [this](metrics::MoveSpec m, const StepWindow& w) { return executed_move(m_s, m, w); },
            f, final);
    }

    const Scenario& m_s;
    const GrblSettings& m_g;
    const Job& m_job;
    const avr::AvrCoreConfig m_avr_cfg;
    const std::vector<std::array<std::int64_t, 2>> m_ends;
    BoardWires m_wires;
    uart::Cp2102 m_cp2102;
    host::GrblSender m_sender;
    avr::AvrCore m_mcu;
    WindowedMoves m_moves;
    std::optional<DrivenPins> m_pins;         // once the recorder watches the pins
    std::optional<StepWindowFold> m_windows;  // with them
    bool m_whole_logs = false;
    std::unique_ptr<BoardLineFaults> m_faults;  // with faults on the link's wires
};

void GrblController::report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) {
    // A setting the firmware refuses is the scenario's (or the machine's) to mend: bad input, no result.
    if (const std::optional<host::grbl::LineError>& refused = m_sender.stream().refused_setting()) {
        throw BadInput(refused->line.where, "the firmware " + m_avr_cfg.firmware_elf + " answered " + refused->answer +
                                                " to the grbl setting " + refused->line.text);
    }
    const GrblFacts facts{
        m_sender,
        m_cp2102,
        m_mcu,
        m_avr_cfg.firmware_elf,
        m_g.protocol == host::grbl::Protocol::CharacterCounting ? "character-counting" : "send-response",
        m_mcu.chip().rx_clock().baud()};
    run.warnings = grbl_warnings(facts);
    run.details = grbl_details_json(facts);
    run.details_text = grbl_details_text(facts);
    run.clock = oscillator_json(m_g.board.clock, m_mcu.chip().clock());
    run.clock_text = oscillator_text(m_g.board.clock, m_mcu.chip().clock());
    if (m_faults) {
        m_faults->take_host_bytes(m_cp2102);
        const BoardLineFaultResult r = m_faults->result(m_mcu);
        run.details["faults"] = board_faults_json(m_s.faults, r);
        run.details_text += board_faults_text(m_s.faults, r);
    }
    report_usb_spikes(m_s.faults, m_cp2102, run);
    report_host_stall(m_s.faults.host_stall, m_sender.stalled_ps(), run);
    if (const std::optional<std::string> why =
            board_link_failure(m_mcu, m_cp2102, m_sender.failure(), m_faults != nullptr)) {
        run.ok = false;
        run.failure = stopped_at(*why, end.t_ps);
    } else if (!m_sender.finished()) {
        run.ok = false;
        run.failure = "the job did not finish: " + time_limit_text(budget, end);
    }
}

}  // namespace

ArchRun Entry::run(const Scenario& s, const Job& job) {
    return run_on_machine(s, job, [](const Scenario& sc, const Job& j, MachinePins& pins) {
        const GrblSettings& g = sc.settings<GrblSettings>();
        avr::AvrCoreConfig avr_cfg =
            board_config(sc, g.board, g.board.firmware,
                         g.board.mcu == "atmega16" ? avr::grbl_atmega16_pin_map() : avr::grbl_pin_map());
        avr_cfg.keep_usart_logs = sc.faults.uart.any();  // board_faults.hpp matches every byte
        const std::optional<FirmwareUsart> usart =
            check_firmware_rate(sc, g.serial.link, avr_cfg, "the firmware " + avr_cfg.firmware_elf);
        std::vector<host::MotionSegment> segments = host::cam(*j.program, sc.machine, host::CamOptions{});
        return std::make_unique<GrblController>(sc, j, pins, std::move(avr_cfg), std::move(segments), usart);
    });
}

}  // namespace cnc::sim::grbl
