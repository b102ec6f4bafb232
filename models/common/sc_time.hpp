// SystemC time as the project's integer picoseconds (the kernel's resolution stays at the default 1 ps).
// Header-only so that cnc_common itself stays free of SystemC; include it only from SystemC modules.
#pragma once
#include <systemc>

#include "common/units.hpp"

namespace cnc {

[[nodiscard]] inline TimePs now_ps() {
    return static_cast<TimePs>(sc_core::sc_time_stamp().value());
}

[[nodiscard]] inline sc_core::sc_time ps_time(TimePs t_ps) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t_ps));
}

// Waits `t_ps` from now (nothing for 0 or less). Call from an SC_THREAD.
inline void wait_ps(TimePs t_ps) {
    if (t_ps > 0) sc_core::wait(ps_time(t_ps));
}

}  // namespace cnc
