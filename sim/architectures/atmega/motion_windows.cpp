#include "architectures/atmega/motion_windows.hpp"

#include <map>
#include <utility>

namespace cnc::sim {

namespace cad2g = host::cad2g;

namespace {

bool both_high(bool en_x_high, bool en_y_high) {
    return en_x_high && en_y_high;
}

}  // namespace

MotionWindowFold::MotionWindowFold(const cad2g::Plan& plan) : m_plan(plan), m_command(command_from(0)) {}

void MotionWindowFold::add(const PortbLines& l, const EdgeLog& y_steps) {
    enum Line { EnX, EnY, Other };
    std::map<TimePs, std::vector<std::pair<Line, bool>>> at;
    const std::pair<const EdgeLog*, Line> logs[] = {
        {&l.en_x, EnX}, {&l.en_y, EnY}, {&l.dir_x, Other}, {&l.dir_y, Other}, {&l.head, Other}};
    for (const auto& [log, line] : logs) {
        for (const Edge& e : log->edges) at[e.t_ps].emplace_back(line, e.level);
    }
    const std::vector<TimePs> y_rises = y_steps.rising();
    std::size_t y_before = 0;   // rises before the event
    std::size_t y_through = 0;  // rises up to it
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
        while (y_before < y_rises.size() && y_rises[y_before] < t) ++y_before;
        while (y_through < y_rises.size() && y_rises[y_through] <= t) ++y_through;
        add(PortEvent{t, en_x, en_y, en_x_rose && !others, m_y_steps + static_cast<std::int64_t>(y_before),
                      m_y_steps + static_cast<std::int64_t>(y_through)});
    }
    m_y_steps += static_cast<std::int64_t>(y_rises.size());
}

void MotionWindowFold::add(const PortEvent& e) {
    const bool both = both_high(e.en_x_high, e.en_y_high);
    if (!m_running) {
        if (m_command && !both) {
            m_open = MotionWindow{*m_command, 0, 0, 0, true, 0, 0};
            begin(e);
        }
        return;
    }
    if (arc() && !last_motion()) {
        if (e.en_x_rise_alone) {
            if (!m_isr) m_isr = e;
            return;
        }
        // The reload: the next chord starts here.
        close(m_isr ? m_isr->t_ps : e.t_ps, m_isr ? m_isr->y_through : e.y_through, true);
        m_open.motion += 1;
        begin(e);
        return;
    }
    if (arc() && e.en_x_rise_alone && !m_isr) m_isr = e;
    if (!both) return;
    close(m_isr ? m_isr->t_ps : e.t_ps, m_isr ? m_isr->y_through : e.y_through, true);
    m_running = false;
    m_command = command_from(m_open.command + 1);
}

void MotionWindowFold::finish(TimePs t_sim_end_ps) {
    if (!m_running) return;
    // An unfinished chord that is not its arc's last may have ended at its ISR all the same.
    const bool chord_ended = arc() && !last_motion() && m_isr;
    close(chord_ended ? m_isr->t_ps : t_sim_end_ps, chord_ended ? m_isr->y_through : m_y_steps, false);
    m_running = false;
}

std::optional<std::size_t> MotionWindowFold::command_from(std::size_t from) const {
    for (std::size_t c = from; c < m_plan.commands.size(); ++c) {
        if (!m_plan.commands[c].motions.empty()) return c;
    }
    return std::nullopt;
}

void MotionWindowFold::begin(const PortEvent& e) {
    m_open.t_begin_ps = e.t_ps;
    m_open.y_steps_before_begin = e.y_before;
    m_isr.reset();
    m_running = true;
}

void MotionWindowFold::close(TimePs t_end_ps, std::int64_t y_through, bool complete) {
    m_open.t_end_ps = t_end_ps;
    m_open.y_steps_through_end = y_through;
    m_open.complete = complete;
    m_windows.push_back(m_open);
}

// Whether the motion under way is an arc's chord: its end is the ISR's (a G00 or G01 is one motion: plan.cpp).
bool MotionWindowFold::arc() const {
    const cad2g::CommandId id = m_plan.commands[m_open.command].id;
    return id == cad2g::CommandId::G02 || id == cad2g::CommandId::G03;
}

bool MotionWindowFold::last_motion() const {
    return m_open.motion + 1 == m_plan.commands[m_open.command].motions.size();
}

std::vector<MotionWindow> motion_windows(const cad2g::Plan& plan, const PortbLines& lines, TimePs t_sim_end_ps) {
    MotionWindowFold fold(plan);
    fold.add(lines, EdgeLog{});
    fold.finish(t_sim_end_ps);
    return {fold.windows().begin(), fold.windows().end()};
}

}  // namespace cnc::sim
