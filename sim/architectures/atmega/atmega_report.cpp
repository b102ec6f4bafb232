#include "architectures/atmega/atmega_report.hpp"

#include <cstdio>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/avr_board/board_link_report.hpp"

namespace cnc::sim {

namespace {

namespace cad2g = host::cad2g;

std::string hex(std::uint8_t b) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", b);
    return text;
}

std::string id_name(cad2g::CommandId id) {
    switch (id) {
        case cad2g::CommandId::G00:
            return "G00";
        case cad2g::CommandId::G01:
            return "G01";
        case cad2g::CommandId::G02:
            return "G02";
        case cad2g::CommandId::G03:
            return "G03";
        case cad2g::CommandId::M30:
            return "M30";
    }
    return "?";
}

nlohmann::json motion_json(const AtmegaFacts& f, cad2g::CommandId id, const cad2g::Motion& m, const MotionWindow* w) {
    nlohmann::json j = {{"line", m.line},
                        {"steps", {m.steps_x, m.steps_y}},
                        {"count_x", m.count_x},
                        {"ocr", {m.ocr_x.value, m.ocr_y.value}},
                        {"ocr_exact", {m.ocr_x.exact, m.ocr_y.exact}},
                        {"portb", hex(m.portb)},
                        {"speed_asked_mm_per_s", {m.speed_x_mm_per_s, m.speed_y_mm_per_s}},
                        {"speed_of_words_mm_per_s",
                         {cad2g::speed_mm_per_s(m.ocr_x.value, f.machine.x.mm_per_step(), f.plan.timer_x),
                          cad2g::speed_mm_per_s(m.ocr_y.value, f.machine.y.mm_per_step(), f.plan.timer_y)}},
                        {"x_timebase", m.x_timebase},
                        {"wrapped", m.wrapped}};
    if (id == cad2g::CommandId::G00) j["count_y"] = m.count_y;
    if (m.y_counted) j["y_counted"] = true;  // timer1-y only: the seed's reports stay as they were
    if (m.chord >= 0) j["chord"] = m.chord;
    if (w != nullptr) {
        j["t_begin_s"] = ps_to_s(w->t_begin_ps);
        j["t_end_s"] = ps_to_s(w->t_end_ps);
        j["complete"] = w->complete;
    }
    return j;
}

nlohmann::json commands_json(const AtmegaFacts& f) {
    std::map<std::pair<std::size_t, std::size_t>, const MotionWindow*> window_of;
    for (const MotionWindow& w : f.windows) window_of[{w.command, w.motion}] = &w;
    nlohmann::json commands = nlohmann::json::array();
    for (std::size_t c = 0; c < f.plan.commands.size(); ++c) {
        const cad2g::Command& cmd = f.plan.commands[c];
        nlohmann::json motions = nlohmann::json::array();
        for (std::size_t m = 0; m < cmd.motions.size(); ++m) {
            const auto w = window_of.find({c, m});
            motions.push_back(motion_json(f, cmd.id, cmd.motions[m], w == window_of.end() ? nullptr : w->second));
        }
        commands.push_back({{"id", id_name(cmd.id)},
                            {"bytes", cad2g::command_bytes(cmd, f.plan.variant).size()},
                            {"motions", motions}});
    }
    return commands;
}

}  // namespace

std::vector<Warning> link_warnings(const AtmegaFacts& f) {
    std::vector<Warning> w = board_link_warnings(f.cp2102, f.mcu);
    const ChordGaps& gaps = f.gaps;
    if (gaps.late > 0) {
        w.push_back({"late_chords", "",
                     std::to_string(gaps.late) +
                         " chords started late (their bytes came after the chord before "
                         "had ended): Y took " +
                         std::to_string(gaps.y_steps_waiting) + " steps meanwhile"});
    }
    return w;
}

nlohmann::json details_json(const AtmegaFacts& f, bool detail) {
    const avr::AvrCoreStats st = f.mcu.stats();
    const ChordGaps& gaps = f.gaps;
    nlohmann::json j = {
        {"firmware", f.firmware},
        {"link", board_link_json(f.cp2102, f.mcu, f.mcu_baud)},
        {"pc",
         {{"transfers", f.pc.transfers().size()},
          {"bytes_written", f.pc.writes().size()},
          {"finished", f.pc.finished()},
          {"stopped", f.pc.failure() ? nlohmann::json(f.pc.failure()->reason) : nlohmann::json(nullptr)},
          {"t_stopped_s", f.pc.failure() ? nlohmann::json(ps_to_s(f.pc.failure()->t_ps)) : nlohmann::json(nullptr)},
          {"t_end_s", f.pc.finished() ? nlohmann::json(ps_to_s(f.pc.t_end_ps())) : nlohmann::json(nullptr)}}},
        {"mcu", {{"cycles", st.cycles}, {"stopped", f.mcu.stopped()}}},
        {"chords",
         {{"late", gaps.late},
          {"wait_max_ms", static_cast<double>(gaps.wait_max_ps) / static_cast<double>(kPsPerMs)},
          {"y_steps_waiting", gaps.y_steps_waiting}}}};
    // The seed's reports stay as they were; a variant names itself.
    if (f.plan.variant != cad2g::Variant::Seed) j["variant"] = cad2g::variant_name(f.plan.variant);
    if (detail) j["commands"] = commands_json(f);  // one record per command and chord: they grow with the job
    return j;
}

std::string details_text(const AtmegaFacts& f) {
    const avr::AvrCoreStats st = f.mcu.stats();
    const ChordGaps& gaps = f.gaps;
    std::map<std::string, std::pair<int, std::size_t>> per_id;  // commands, motions
    for (const cad2g::Command& c : f.plan.commands) {
        auto& n = per_id[id_name(c.id)];
        ++n.first;
        n.second += c.motions.size();
    }
    std::ostringstream t;
    t << "atmega link and host\n";
    if (f.plan.variant != cad2g::Variant::Seed) {
        t << "  avr.variant " << cad2g::variant_name(f.plan.variant) << " (seed 003 §5.6)\n";
    }
    t << board_link_text(f.cp2102, f.mcu_baud) << "  PC wrote " << f.pc.writes().size() << " bytes, one per confirm"
      << (f.pc.failure() ? fmt::format(FMT_STRING(" (stopped at {:.3f} s: {})"), ps_to_s(f.pc.failure()->t_ps),
                                       f.pc.failure()->reason)
                         : std::string())
      << "; framing errors at the MCU " << st.usart.rx_framing_errors << ", at the CP2102 "
      << f.cp2102.stats().framing_errors << '\n'
      << "  commands:";
    for (const auto& [id, n] : per_id) {
        t << ' ' << id << " x" << n.first;
        if (id == "G02" || id == "G03") t << " (" << n.second << " chords)";
    }
    t << '\n'
      << "  chords with late data " << gaps.late
      << fmt::format(FMT_STRING(", longest wait {:.3f} ms, Y steps while waiting "),
                     static_cast<double>(gaps.wait_max_ps) / 1e9)
      << gaps.y_steps_waiting << '\n';
    return t.str();
}

}  // namespace cnc::sim
