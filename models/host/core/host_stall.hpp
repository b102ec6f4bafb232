// A host program held up once (a fault: another process, a swap storm, a USB reset): from from_ps to to_ps it
// neither writes nor reads its port. Every host program that can stall asks before it acts.
#pragma once
#include "common/units.hpp"

namespace cnc::host {

struct StallWindow {
    TimePs from_ps = 0;
    TimePs to_ps = 0;  // empty when to_ps <= from_ps
};

class HostStall {
public:
    explicit HostStall(StallWindow w) : m_w(w) {}

    // How long a program that wishes to act at now_ps must wait first (0 outside the stall); counted.
    TimePs wait_at(TimePs now_ps) {
        if (now_ps < m_w.from_ps || now_ps >= m_w.to_ps) return 0;
        m_held_ps += m_w.to_ps - now_ps;
        return m_w.to_ps - now_ps;
    }
    // How long the stall held the program up: from its first wish to act in the stall to the stall's end.
    [[nodiscard]] TimePs held_ps() const { return m_held_ps; }

private:
    StallWindow m_w;
    TimePs m_held_ps = 0;
};

}  // namespace cnc::host
