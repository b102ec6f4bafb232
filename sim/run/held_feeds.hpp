// Where the job asks a feed faster than the machine's axes allow. Every architecture holds a move to the axis
// velocity limits (host::feed_within_axis_limits; docs/scenario-reference.md, machine.<axis>.max_velocity_mm_per_s),
// so the job gets less than it asked without an error, and the feed error (docs/metrics.md) is measured against
// the F it asked. One warning per run of consecutive moves that ask, and are held to, the same feeds: a job at
// one too-high F gives one line, not one per move.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/warning.hpp"
#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::sim {

// The feed a cutting move runs at within the axis velocity limits, mm/min: its F when both axes allow it, else the
// lowest over the move (an arc's where its tangent runs most along the limiting axis); and the axis whose limit
// holds it ('x' or 'y'; 0 when F is within both). A rapid runs at the machine's rapid speed, not a job's F: none.
struct HeldFeed {
    double feed_mm_per_min = 0.0;
    char axis = 0;
};
[[nodiscard]] HeldFeed held_feed(const host::ProgrammedMove& m, const host::MachineModel& machine);

class HeldFeedWarnings {
public:
    // `machine` must outlive it; `filename` places the warnings.
    HeldFeedWarnings(const host::MachineModel& machine, std::string filename);
    // The next programmed move of the job, in order.
    void add(const host::ProgrammedMove& m);
    // The warnings, after the last move.
    void finish(std::vector<Warning>& out);

private:
    struct Held {
        int first_line = 0;
        int last_line = 0;
        double asked_mm_per_min = 0.0;
        HeldFeed held;
        bool by_x = false;  // the axes whose limits held the run's moves
        bool by_y = false;
    };
    void close();

    const host::MachineModel& m_machine;
    std::string m_file;
    std::optional<Held> m_open;  // the run of held moves the previous move belongs to
    std::vector<Warning> m_done;
};

}  // namespace cnc::sim
