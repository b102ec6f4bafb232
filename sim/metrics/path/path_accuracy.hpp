// Path accuracy: the tool position against the programmed path (contour error), against the move's
// commanded end points (endpoint error) and against the programmed timed trajectory (following error).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct MovePath {
    std::size_t samples = 0;  // tool samples attributed to the move
    std::optional<double> contour_max_um;
    std::optional<double> following_max_um, following_rms_um;
    std::optional<double> endpoint_vs_command_um;  // tool at t_end vs the move's to_mm
    std::optional<double> endpoint_vs_program_um;  // only on the last piece of a programmed move
};

struct PathResult {
    std::vector<MovePath> moves;
    std::size_t samples = 0;
    std::optional<double> contour_max_um, contour_rms_um;
    std::optional<double> following_max_um, following_rms_um;
    std::optional<double> endpoint_vs_command_max_um, endpoint_vs_program_max_um;
    std::optional<double> job_end_um;  // last tool sample vs the last move's programmed end
};

// Samples are attributed to moves with MoveTimeline; samples before the first move go to the first.
// Contour error takes the nearest of the active move's path and its neighbours' (a sample near a
// corner may be nearer the next segment). Following error runs along from_mm -> to_mm at the move's
// F from its first step edge (t_begin if it has none), held at from_mm before and at to_mm after; with a
// commanded trajectory (RunInput::commanded) it is the distance to that trajectory at the sample's time, taken
// for the tool both just before and just after the step: the tool stands still between samples, so over a
// sample interval the distance to a straight commanded path is largest at one of the interval's ends.
// Rapid moves are included in every figure (their F is their own rapid feed); the per-move table
// says which moves are rapid. Needs tool samples and moves; otherwise all figures are empty.
[[nodiscard]] PathResult compute_path_accuracy(const RunInput& in, const EdgeIndex& idx);

// The errors of tool sample i as compute_path_accuracy measures them (the plots draw them along the job); needs
// moves, and i < in.tool.size().
struct SampleError {
    std::size_t move = 0;  // the active move the sample is attributed to
    double contour_um = 0.0;
    double following_um = 0.0;
};
[[nodiscard]] SampleError sample_error(const RunInput& in, const EdgeIndex& idx, const MoveTimeline& timeline,
                                       std::size_t i);

}  // namespace cnc::metrics
