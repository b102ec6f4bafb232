// A dominant step of step_gen's ramps (fpga/core/step_ramp.hpp) as the ramp tests compare them: its RUN clock and
// whether the other axis stepped with it.
#pragma once
#include <cstdint>
#include <ostream>

namespace cnc::fpga::test {

struct RampStep {
    std::int64_t clock;
    bool sub;
    bool operator==(const RampStep& o) const { return clock == o.clock && sub == o.sub; }
};

inline std::ostream& operator<<(std::ostream& os, const RampStep& s) {
    return os << "{" << s.clock << ", " << s.sub << "}";
}

}  // namespace cnc::fpga::test
