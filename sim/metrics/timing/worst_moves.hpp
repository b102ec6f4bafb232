// The moves that did worst on each per-move figure, so that the summary of a long job says where to look (by move
// index and G-code line). Moves without the figure (no tool samples, no feed measured) are left out. Folded move by
// move in bounded memory (the streaming metrics need not keep the moves for them).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace cnc::metrics {

struct MoveMetrics;

inline constexpr std::size_t kWorstMovesListed = 5;

struct RankedMove {
    std::size_t move = 0;  // position in the job's programmed moves (RunMetrics::moves)
    int index = 0;         // MoveMetrics::index and line
    int line = 0;
    double value = 0.0;  // the figure, signed as the move has it
};

// Each list worst first by the figure's magnitude; equal magnitudes in move order.
struct WorstMoves {
    std::vector<RankedMove> contour;    // contour_max_um
    std::vector<RankedMove> following;  // following_max_um
    std::vector<RankedMove> feed;       // feed_error_pct
};

class WorstMovesFold {
public:
    explicit WorstMovesFold(std::size_t n = kWorstMovesListed) : m_n(n) {}
    // The job's programmed moves in order.
    void add(const MoveMetrics& move);
    [[nodiscard]] const WorstMoves& lists() const { return m_lists; }

private:
    void rank(std::vector<RankedMove>& list, const MoveMetrics& move, const std::optional<double>& figure) const;

    std::size_t m_n;
    std::size_t m_added = 0;
    WorstMoves m_lists;
};

// The one-fold case.
[[nodiscard]] WorstMoves worst_moves(const std::vector<MoveMetrics>& moves, std::size_t n = kWorstMovesListed);

}  // namespace cnc::metrics
