#include "metrics/timing/job_gaps.hpp"

#include <optional>

namespace cnc::metrics {

std::vector<JobGap> job_gaps(const MoveRecords& moves, const std::vector<MoveMetrics>& pieces) {
    std::size_t piece_count = 0;
    moves.for_each([&piece_count](const MoveMetrics& m) { piece_count += m.pieces; });
    std::vector<JobGap> gaps;
    if (piece_count != pieces.size()) return gaps;
    struct Stepped {
        std::size_t move, piece;
        TimePs t_last_edge_ps;
    };
    std::optional<Stepped> last;  // the last piece that stepped
    std::size_t move = 0;
    std::size_t piece = 0;
    moves.for_each([&](const MoveMetrics& m) {
        for (const std::size_t end = piece + m.pieces; piece < end; ++piece) {
            const MoveMetrics& p = pieces[piece];
            if (!p.t_first_edge_ps) continue;
            if (last) gaps.push_back({last->move, move, last->piece, piece, *p.t_first_edge_ps - last->t_last_edge_ps});
            last = Stepped{move, piece, *p.t_last_edge_ps};
        }
        ++move;
    });
    return gaps;
}

}  // namespace cnc::metrics
