#include "metrics/pulse/edge_index.hpp"

#include <algorithm>
#include <stdexcept>

namespace cnc::metrics {

namespace {

void require_time_order(const EdgeLog& log) {
    const bool sorted = std::is_sorted(log.edges.begin(), log.edges.end(),
                                       [](const Edge& a, const Edge& b) { return a.t_ps < b.t_ps; });
    if (!sorted) throw std::invalid_argument("edge log '" + log.name + "' is not in time order");
}

}  // namespace

AxisEdges extract_edges(const AxisTrace& axis) {
    require_time_order(axis.step);
    require_time_order(axis.dir);
    AxisEdges out;
    out.rising = axis.step.rising();
    out.falling = axis.step.count_falling();
    bool level = axis.dir.initial;
    for (const Edge& e : axis.dir.edges) {
        if (e.level != level) out.dir_changes.push_back(e.t_ps);
        level = e.level;
    }
    out.rising_sign.reserve(out.rising.size());
    for (const TimePs t : out.rising) {
        out.rising_sign.push_back(axis.dir.level_at(t) == axis.dir_high_is_positive ? 1 : -1);
    }
    return out;
}

MoveTimeline::MoveTimeline(const std::vector<MoveSpec>& moves) {
    m_begin_ps.reserve(moves.size());
    for (const MoveSpec& m : moves) {
        if (!m_begin_ps.empty() && m.t_begin_ps < m_begin_ps.back()) {
            throw std::invalid_argument("moves are not sorted by t_begin_ps (move " + std::to_string(m.index) + ")");
        }
        m_begin_ps.push_back(m.t_begin_ps);
    }
}

std::optional<std::size_t> MoveTimeline::active_at(TimePs t_ps) const {
    const auto it = std::upper_bound(m_begin_ps.begin(), m_begin_ps.end(), t_ps);
    if (it == m_begin_ps.begin()) return std::nullopt;
    return static_cast<std::size_t>(std::prev(it) - m_begin_ps.begin());
}

std::vector<EdgeRange> MoveTimeline::split(const std::vector<TimePs>& sorted_times) const {
    std::vector<EdgeRange> out(m_begin_ps.size());
    for (std::size_t i = 0; i < m_begin_ps.size(); ++i) {
        const auto first = std::lower_bound(sorted_times.begin(), sorted_times.end(), m_begin_ps[i]);
        const auto last = i + 1 < m_begin_ps.size() ? std::lower_bound(first, sorted_times.end(), m_begin_ps[i + 1])
                                                    : sorted_times.end();
        out[i] = {static_cast<std::size_t>(first - sorted_times.begin()),
                  static_cast<std::size_t>(last - sorted_times.begin())};
    }
    return out;
}

EdgeIndex index_edges(const RunInput& in) {
    EdgeIndex idx;
    const MoveTimeline timeline(in.moves);
    idx.move_first_edge_ps.assign(in.moves.size(), std::nullopt);
    idx.move_last_edge_ps.assign(in.moves.size(), std::nullopt);
    for (const AxisTrace& trace : in.axes) {
        AxisEdges edges = extract_edges(trace);
        std::size_t unattributed = 0;
        if (!in.moves.empty()) {
            std::vector<EdgeRange> ranges = timeline.split(edges.rising);
            unattributed = ranges.front().begin;
            for (std::size_t m = 0; m < ranges.size(); ++m) {
                if (ranges[m].empty()) continue;
                const TimePs first = edges.rising[ranges[m].begin];
                const TimePs last = edges.rising[ranges[m].end - 1];
                auto& f = idx.move_first_edge_ps[m];
                auto& l = idx.move_last_edge_ps[m];
                f = f ? std::min(*f, first) : first;
                l = l ? std::max(*l, last) : last;
            }
            idx.by_move.push_back(std::move(ranges));
        }
        idx.unattributed.push_back(unattributed);
        idx.axes.push_back(std::move(edges));
    }
    return idx;
}

std::string axis_label(const RunInput& in, std::size_t i) {
    if (i < in.axes.size() && !in.axes[i].name.empty()) return in.axes[i].name;
    static const char* const kNames[] = {"x", "y", "z", "a", "b", "c"};
    if (i < std::size(kNames)) return kNames[i];
    return "axis" + std::to_string(i);
}

}  // namespace cnc::metrics
