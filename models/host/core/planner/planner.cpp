#include "host/core/planner/planner.hpp"

#include <cstddef>

#include "host/core/planner/plan_stream.hpp"

namespace cnc::host::planner {

Trajectory plan(const Program& program, const PlannerConfig& cfg) {
    PlanStream stream(cfg, program.filename);
    std::size_t w = 0;  // the waits are in the program's order, each before the move it precedes
    for (std::size_t i = 0; i < program.moves.size(); ++i) {
        for (; w < program.waits.size() && program.waits[w].before_move <= i; ++w) {
            stream.add_wait(program.waits[w].seconds);
        }
        stream.add_move(program.moves[i]);
    }
    for (; w < program.waits.size(); ++w) stream.add_wait(program.waits[w].seconds);
    stream.finish();
    return Trajectory(stream.take_pieces(), stream.take_windows(), stream.rest_mm(), stream.end_hold_s());
}

}  // namespace cnc::host::planner
