// The programmed moves' records of a run (RunMetrics::moves), the largest per-move block of its metrics: what the
// report's move columns and the dead-time gaps read. Kept in memory for short runs (compute_metrics, the plots,
// the tests); a streamed run spills them to a temporary file (docs/streaming.md), so that its memory does not
// grow with its moves. The file is unlinked as soon as it is made: nothing is left behind at exit or on error.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/move_metrics.hpp"

namespace cnc::metrics {

// A write or read of the spill file failed (a full disk): the run fails (exit 1), the message names the file.
class MoveRecordsError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class MoveRecords {
public:
    MoveRecords();  // in memory
    explicit MoveRecords(std::vector<MoveMetrics> moves);
    // Spilled to a new unlinked file in `dir` ($TMPDIR, else /tmp, when empty) in fixed-size rows of the fields
    // the report reads, the per-axis ones for up to `axes` axes (MoveMetrics::sync_unmatched_edges is left out:
    // only compute_metrics reads it, of the pieces). Throws MoveRecordsError when the file cannot be made.
    static MoveRecords spilled(std::size_t axes, const std::string& dir = {});
    // The same on a file already open for reading and writing (and unlinked), named `path` in messages; the
    // records own `fd` from now on.
    static MoveRecords spilled_to(std::size_t axes, int fd, std::string path);

    MoveRecords(MoveRecords&&) noexcept;
    MoveRecords& operator=(MoveRecords&&) noexcept;
    ~MoveRecords();

    // The next programmed move, in job order.
    void append(const MoveMetrics& move);
    [[nodiscard]] std::size_t size() const;
    [[nodiscard]] bool empty() const { return size() == 0; }
    // One pass over the moves in order (as many as the reader needs); the record handed over lives for the call.
    void for_each(const std::function<void(const MoveMetrics&)>& visit) const;
    [[nodiscard]] MoveMetrics at(std::size_t i) const;  // std::out_of_range past the end
    [[nodiscard]] MoveMetrics operator[](std::size_t i) const { return at(i); }

private:
    class Spill;
    std::vector<MoveMetrics> m_memory;
    std::unique_ptr<Spill> m_spill;
};

// The dead-time gaps between the programmed moves, in job order (a detailed report's list: held whole).
[[nodiscard]] std::vector<DeadGap> dead_gaps(const MoveRecords& moves);

}  // namespace cnc::metrics
