#include "metrics/timing/programmed_moves.hpp"

#include <algorithm>

namespace cnc::metrics {

bool same_programmed_move(const MoveSpec& a, const MoveSpec& b) {
    return a.programmed >= 0 && a.programmed == b.programmed;
}

std::vector<ProgrammedMove> programmed_moves(const RunInput& in, const EdgeIndex& idx) {
    std::vector<ProgrammedMove> out;
    for (std::size_t p = 0; p < in.moves.size(); ++p) {
        if (out.empty() || !same_programmed_move(in.moves[p - 1], in.moves[p])) {
            ProgrammedMove pm;
            pm.first_piece = p;
            for (std::size_t a = 0; a < idx.axes.size(); ++a) {
                const std::size_t at = idx.by_move[a][p].begin;
                pm.edges.push_back({at, at});
            }
            out.push_back(std::move(pm));
        }
        ProgrammedMove& pm = out.back();
        pm.end_piece = p + 1;
        for (std::size_t a = 0; a < idx.axes.size(); ++a) pm.edges[a].end = idx.by_move[a][p].end;
        if (const std::optional<TimePs> f = idx.move_first_edge_ps[p]) {
            pm.t_first_edge_ps = pm.t_first_edge_ps.value_or(*f);
            pm.t_last_edge_ps =
                std::max(pm.t_last_edge_ps.value_or(*idx.move_last_edge_ps[p]), *idx.move_last_edge_ps[p]);
        }
    }
    return out;
}

}  // namespace cnc::metrics
