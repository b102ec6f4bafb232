#include "host/core/planner/planner.hpp"

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "host/core/planner/plan_stream.hpp"

namespace cnc::host::planner {

namespace {

template <typename T>
void append(std::vector<T>& to, std::vector<T> from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

}  // namespace

Trajectory plan(const Program& program, const PlannerConfig& cfg) {
    PlanStream stream(cfg, program.filename);
    std::vector<PlannedPiece> pieces;
    std::vector<std::pair<double, double>> windows;
    std::size_t w = 0;  // the waits are in the program's order, each before the move it precedes
    for (std::size_t i = 0; i < program.moves.size(); ++i) {
        for (; w < program.waits.size() && program.waits[w].before_move <= i; ++w) {
            stream.add_wait(program.waits[w].seconds);
        }
        stream.add_move(program.moves[i]);
        // Taken as they are final, so that the stream holds only the look-ahead window.
        append(pieces, stream.take_pieces());
        append(windows, stream.take_windows());
    }
    for (; w < program.waits.size(); ++w) stream.add_wait(program.waits[w].seconds);
    stream.finish();
    append(pieces, stream.take_pieces());
    append(windows, stream.take_windows());
    // Held through the whole run: no spare capacity.
    pieces.shrink_to_fit();
    windows.shrink_to_fit();
    return Trajectory(std::move(pieces), std::move(windows), stream.rest_mm(), stream.end_hold_s());
}

}  // namespace cnc::host::planner
