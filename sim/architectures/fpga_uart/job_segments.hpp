// The fpga-uart host's job as its motion segments, made as the sender asks for them: a G-code job is read from
// its file again one programmed move at a time and put through the seed 000 CAM (GCODE2STEPS), so that the run
// holds one move's segments ahead of the link instead of the whole program; a steps file is its rows.
#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "host/core/host_waits.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// A programmed move too short for one microstep on every axis: it makes no segment (run/moves.hpp).
struct UnsteppedMove {
    int move = 0;  // 0-based in the program
    host::ProgrammedMove programmed;
};

struct MadeSegment {
    host::MotionSegment seg;
    std::optional<host::ProgrammedMove> programmed;  // its programmed move; none for a steps-file row
    double wait_before_s = 0.0;                      // the job's host wait before it (dwell, pause, Z move)
    std::vector<UnsteppedMove> unstepped_before;     // the programmed moves between the last segment's and its
};

// The segments in order. Throws as host::cam() does (a caller that must not fail mid-run reads them all once
// before). `s` and `job` must outlive it.
class JobSegments {
public:
    JobSegments(const Scenario& s, const Job& job);
    [[nodiscard]] std::optional<MadeSegment> next();  // none after the last
    [[nodiscard]] double wait_after_last_s();         // once next() has returned none
    // Once next() has returned none: the programmed moves after the last segment's.
    [[nodiscard]] std::vector<UnsteppedMove> take_unstepped_after_last() { return std::move(m_unstepped); }

private:
    const Job& m_job;
    std::unique_ptr<host::GcodeStream> m_moves;  // G-code: the file, read again
    std::optional<host::CamStream> m_cam;
    std::optional<host::UnitWaitLayer> m_waits;
    std::deque<host::MotionSegment> m_pending;   // the current programmed move's segments not handed over yet
    std::optional<host::ProgrammedMove> m_move;  // the current programmed move
    std::vector<UnsteppedMove> m_unstepped;      // read since the last segment handed over
    std::size_t m_next = 0;                      // programmed move, or steps-file row, to read next
};

}  // namespace cnc::sim
