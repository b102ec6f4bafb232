// One move's measured figures: a programmed move's (RunMetrics::moves) or an executed piece's (RunMetrics::pieces).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "metrics/path/path_accuracy.hpp"
#include "metrics/run_input.hpp"
#include "metrics/timing/move_timing.hpp"

namespace cnc::metrics {

// What the program asked for: the move's kind and where it ends (machine mm, work offsets applied), whatever the
// controller cut it into.
enum class ProgrammedKind : std::uint8_t { Rapid, Line, ArcCw, ArcCcw };

struct ProgrammedEnd {
    ProgrammedKind kind = ProgrammedKind::Line;
    double x_mm = 0.0, y_mm = 0.0, z_mm = 0.0;
    std::optional<double> center_x_mm, center_y_mm;  // arcs
};

// The programmed end of a piece's move (its MoveSpec::path, the parent arc of a chord).
[[nodiscard]] ProgrammedEnd programmed_end(const MoveSpec& spec);
[[nodiscard]] const char* to_string(ProgrammedKind kind);

// A programmed move (RunMetrics::moves) or one executed piece of it (RunMetrics::pieces): a programmed move sums
// its pieces' steps and takes the worst of their figures; timing is defined on programmed moves only.
struct MoveMetrics {
    int index = 0;  // programmed move: 1-based in the job (a steps-file row: the row); piece: the piece's own
    int line = 0;
    std::size_t pieces = 1;
    double feed_mm_per_min = 0.0;
    std::vector<std::int64_t> steps_commanded;              // [axis]
    std::vector<std::int64_t> steps_emitted;                // [axis] rising edges signed by DIR
    std::optional<TimePs> t_first_edge_ps, t_last_edge_ps;  // any axis
    std::vector<std::optional<double>> sync_max_abs_ns;     // [axis]
    std::vector<std::size_t> sync_unmatched_edges;          // [axis], with a commanded trajectory (sync_error.hpp)
    MoveTiming timing;
    MovePath path;
    ProgrammedEnd programmed;
    [[nodiscard]] bool rapid() const { return programmed.kind == ProgrammedKind::Rapid; }
};

}  // namespace cnc::metrics
