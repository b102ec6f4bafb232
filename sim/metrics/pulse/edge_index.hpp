// The STEP/DIR edges of every axis in the form the metric families share: sorted edge times, the
// direction of each step, and which move each rising edge belongs to.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

// Half-open range [begin, end) of indices into one axis's rising edges.
struct EdgeRange {
    std::size_t begin = 0;
    std::size_t end = 0;
    [[nodiscard]] std::size_t size() const { return end - begin; }
    [[nodiscard]] bool empty() const { return end == begin; }
};

struct AxisEdges {
    std::vector<TimePs> rising;
    std::size_t falling = 0;  // falling STEP edges: only counted
    std::vector<TimePs> dir_changes;
    std::vector<int> rising_sign;  // +1 / -1 per rising edge: the DIR level at that instant, with the polarity applied
};

// Edges of one axis. Throws std::invalid_argument if a log is not in time order.
[[nodiscard]] AxisEdges extract_edges(const AxisTrace& axis);

// Which move is active at a time: the last move whose t_begin is at or before it. An instant on a
// boundary therefore belongs to the later move, and the gap after a move's t_end (until the next move
// begins) still belongs to that move, so an edge the controller emits just after reporting "done" is
// not lost.
class MoveTimeline {
public:
    // Throws std::invalid_argument if the moves are not sorted by t_begin_ps.
    explicit MoveTimeline(const std::vector<MoveSpec>& moves);

    [[nodiscard]] std::optional<std::size_t> active_at(TimePs t_ps) const;
    // Splits sorted times into one range per move; the times before the first move are in none.
    [[nodiscard]] std::vector<EdgeRange> split(const std::vector<TimePs>& sorted_times) const;
    [[nodiscard]] std::size_t size() const { return m_begin_ps.size(); }

private:
    std::vector<TimePs> m_begin_ps;
};

struct EdgeIndex {
    std::vector<AxisEdges> axes;
    std::vector<std::vector<EdgeRange>> by_move;            // [axis][move]; empty without moves
    std::vector<std::size_t> unattributed;                  // [axis] rising edges before the first move
    std::vector<std::optional<TimePs>> move_first_edge_ps;  // [move] first rising edge on any axis
    std::vector<std::optional<TimePs>> move_last_edge_ps;   // [move] last rising edge on any axis
};

[[nodiscard]] EdgeIndex index_edges(const RunInput& in);

// Report label of axis i: its name, else x, y, z, a, b, c, then "axis<i>".
[[nodiscard]] std::string axis_label(const RunInput& in, std::size_t i);

}  // namespace cnc::metrics
