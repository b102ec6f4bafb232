// One axis's STEP and DIR edges from the instants it is to step at, as a perfect step generator drives a DRV8825:
// STEP rises at each instant and stays high kStepHighPs, DIR turns kDirLeadPs before the first rise of a new
// direction. Where rises come closer than the driver allows (DRV8825 data sheet, SLVSA73F §7.6: tWH, tWL >= 1.9 us,
// tSU, tH(DIR) >= 650 ns), the edges go halfway between the rises instead, so that every rise still lands at its
// instant and the driver's timing check reports the crowding.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "common/units.hpp"

namespace cnc::sim::ideal {

inline constexpr TimePs kStepHighPs = 2 * kPsPerUs;  // tWH(STEP) >= 1.9 us, rounded up to the microsecond
inline constexpr TimePs kDirLeadPs = kPsPerUs;       // tSU(DIR) >= 650 ns, with margin

struct PinEdge {
    TimePs t_ps = 0;
    bool step = false;  // the STEP pin, else DIR
    bool level = false;
};

class StepTrain {
public:
    // DIR's level for the positive direction; DIR starts low.
    explicit StepTrain(bool dir_high_is_positive = true) : m_positive_level(dir_high_is_positive) {}

    // A step at t_ps in `direction` (+1, -1), after every one added before.
    void add(TimePs t_ps, int direction);
    // No step comes before t_ps any more.
    void advance(TimePs t_ps);
    // No step comes any more.
    void finish();

    // Every edge before this time has been made (the edges of the steps still to come are later).
    [[nodiscard]] TimePs final_until_ps() const;
    // The edges made so far, in time order, handed over once.
    [[nodiscard]] std::vector<PinEdge> take();

private:
    void fall_at(TimePs t_ps);

    bool m_positive_level;
    bool m_dir_level = false;
    std::optional<TimePs> m_last_rise_ps;
    bool m_fall_pending = false;
    TimePs m_scanned_ps = 0;
    std::vector<PinEdge> m_edges;
};

}  // namespace cnc::sim::ideal
