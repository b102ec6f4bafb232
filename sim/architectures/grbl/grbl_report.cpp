#include "architectures/grbl/grbl_report.hpp"

#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/avr_board/board_link_report.hpp"

namespace cnc::sim {

namespace {

std::size_t status_queries(const host::GrblSender& sender) {
    std::size_t n = 0;
    for (const host::GrblLineRecord& r : sender.lines()) n += r.written && r.text == "?" ? 1 : 0;
    return n;
}

}  // namespace

std::vector<Warning> grbl_warnings(const GrblFacts& f) {
    std::vector<Warning> w = board_link_warnings(f.cp2102, f.mcu);
    for (const host::grbl::LineError& e : f.sender.stream().errors()) {
        w.push_back({"grbl_error", e.line.where, "grbl answered " + e.answer + " to " + e.line.text});
    }
    return w;
}

nlohmann::json grbl_details_json(const GrblFacts& f) {
    const host::grbl::Stream& s = f.sender.stream();
    nlohmann::json errors = nlohmann::json::array();
    for (const host::grbl::LineError& e : s.errors()) {
        errors.push_back({{"where", e.line.where}, {"line", e.line.text}, {"answer", e.answer}});
    }
    return {{"firmware", f.firmware},
            {"banner", s.banner()},
            {"link", board_link_json(f.cp2102, f.mcu, f.mcu_baud)},
            {"sender",
             {{"protocol", f.protocol},
              {"lines_sent", s.job_lines_sent()},
              {"lines_answered", s.job_lines_answered()},
              {"most_bytes_in_flight", s.most_in_flight_bytes()},
              {"status_queries", status_queries(f.sender)},
              {"last_status", s.last_status()},
              {"errors", errors},
              {"finished", f.sender.finished()},
              {"t_end_s", f.sender.finished() ? nlohmann::json(ps_to_s(f.sender.t_end_ps())) : nlohmann::json()},
              {"stopped", f.sender.failure() ? nlohmann::json(*f.sender.failure()) : nlohmann::json()}}},
            {"mcu", {{"cycles", f.mcu.stats().cycles}}}};
}

std::string grbl_details_text(const GrblFacts& f) {
    const host::grbl::Stream& s = f.sender.stream();
    std::ostringstream t;
    t << "grbl link and sender\n"
      << "  firmware " << f.firmware << ": \"" << s.banner() << "\"\n"
      << board_link_text(f.cp2102, f.mcu_baud)
      << fmt::format(FMT_STRING("  {} lines sent ({}), {} answered, at most {} bytes in flight, {} status queries, "
                                "{} errors\n"),
                     s.job_lines_sent(), f.protocol, s.job_lines_answered(), s.most_in_flight_bytes(),
                     status_queries(f.sender), s.errors().size());
    if (f.sender.failure()) t << "  stopped: " << *f.sender.failure() << '\n';
    return t.str();
}

}  // namespace cnc::sim
