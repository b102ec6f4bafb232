#include "systems/atmega/motion_windows.hpp"

#include <algorithm>
#include <map>
#include <optional>

namespace cnc::sim {

namespace {

namespace s3 = host::seed003;

// The PORTB pins at one instant where any of them changed.
struct PortEvent {
    TimePs t_ps = 0;
    bool en_x_high = false;
    bool en_y_high = false;
    bool en_x_rise_alone = false;  // the end of an ISR count: nothing but EN_X, rising
};

std::vector<PortEvent> port_events(const PortbLines& l) {
    enum Line { EnX, EnY, Other };
    std::map<TimePs, std::vector<std::pair<Line, bool>>> at;
    const std::pair<const EdgeLog*, Line> logs[] = {
        {&l.en_x, EnX}, {&l.en_y, EnY}, {&l.dir_x, Other}, {&l.dir_y, Other}, {&l.head, Other}};
    for (const auto& [log, line] : logs) {
        for (const Edge& e : log->edges) at[e.t_ps].emplace_back(line, e.level);
    }
    std::vector<PortEvent> events;
    bool en_x = l.en_x.initial;
    bool en_y = l.en_y.initial;
    for (const auto& [t, changes] : at) {
        bool others = false;
        bool en_x_rose = false;
        for (const auto& [line, level] : changes) {
            if (line == EnX) {
                en_x_rose = level && !en_x;
                en_x = level;
            } else if (line == EnY) {
                others = true;
                en_y = level;
            } else {
                others = true;
            }
        }
        events.push_back({t, en_x, en_y, en_x_rose && !others});
    }
    return events;
}

bool both_high(const PortEvent& e) { return e.en_x_high && e.en_y_high; }

class Walker {
public:
    Walker(std::vector<PortEvent> events, TimePs t_sim_end_ps) : m_ev(std::move(events)), m_t_sim_end(t_sim_end_ps) {}

    // First event at or after the cursor matching `pred`.
    template <class Pred>
    std::optional<std::size_t> find(std::size_t from, Pred pred) const {
        for (std::size_t i = from; i < m_ev.size(); ++i) {
            if (pred(m_ev[i])) return i;
        }
        return std::nullopt;
    }
    [[nodiscard]] TimePs t(std::size_t i) const { return m_ev[i].t_ps; }
    [[nodiscard]] TimePs t_sim_end() const { return m_t_sim_end; }

private:
    std::vector<PortEvent> m_ev;
    TimePs m_t_sim_end;
};

}  // namespace

std::vector<MotionWindow> motion_windows(const s3::Plan& plan, const PortbLines& lines, TimePs t_sim_end_ps) {
    const Walker w(port_events(lines), t_sim_end_ps);
    std::vector<MotionWindow> out;
    std::size_t cursor = 0;
    for (std::size_t c = 0; c < plan.commands.size(); ++c) {
        const s3::Command& cmd = plan.commands[c];
        if (cmd.motions.empty()) continue;
        const auto start = w.find(cursor, [](const PortEvent& e) { return !both_high(e); });
        if (!start) break;
        const bool arc = cmd.id == s3::CommandId::G02 || cmd.id == s3::CommandId::G03;
        std::size_t at = *start;
        for (std::size_t m = 0; m < cmd.motions.size(); ++m) {
            MotionWindow win{c, m, w.t(at), w.t_sim_end(), false};
            const bool last = m + 1 == cmd.motions.size();
            if (arc && !last) {
                const auto isr = w.find(at + 1, [](const PortEvent& e) { return e.en_x_rise_alone; });
                const auto next = w.find(at + 1, [](const PortEvent& e) { return !e.en_x_rise_alone; });
                if (!next) {
                    if (isr) win.t_end_ps = w.t(*isr);
                    out.push_back(win);
                    return out;
                }
                win.t_end_ps = isr && *isr < *next ? w.t(*isr) : w.t(*next);
                win.complete = true;
                out.push_back(win);
                at = *next;
                continue;
            }
            const auto end = w.find(at + 1, both_high);
            if (!end) {
                out.push_back(win);
                return out;
            }
            const auto isr = arc ? w.find(at + 1, [](const PortEvent& e) { return e.en_x_rise_alone; }) : std::nullopt;
            win.t_end_ps = isr && *isr <= *end ? w.t(*isr) : w.t(*end);
            win.complete = true;
            out.push_back(win);
            cursor = *end + 1;
        }
    }
    return out;
}

}  // namespace cnc::sim
