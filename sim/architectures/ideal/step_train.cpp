#include "architectures/ideal/step_train.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace cnc::sim::ideal {

void StepTrain::fall_at(TimePs t_ps) {
    m_edges.push_back({t_ps, true, false});
    m_fall_pending = false;
}

void StepTrain::add(TimePs t_ps, int direction) {
    const TimePs previous_ps = m_last_rise_ps.value_or(0);
    const TimePs midway_ps = previous_ps + (t_ps - previous_ps) / 2;
    if (m_fall_pending) fall_at(std::min(previous_ps + kStepHighPs, midway_ps));
    const bool level = (direction > 0) == m_positive_level;
    if (level != m_dir_level) {
        m_edges.push_back({std::max(t_ps - kDirLeadPs, midway_ps), false, level});
        m_dir_level = level;
    }
    m_edges.push_back({t_ps, true, true});
    m_last_rise_ps = t_ps;
    m_fall_pending = true;
    m_scanned_ps = t_ps;
}

void StepTrain::advance(TimePs t_ps) {
    m_scanned_ps = std::max(m_scanned_ps, t_ps);
    // A rise at or after t_ps leaves the pending fall its whole high time once t_ps is two high times past.
    if (m_fall_pending && m_scanned_ps >= *m_last_rise_ps + 2 * kStepHighPs) fall_at(*m_last_rise_ps + kStepHighPs);
}

void StepTrain::finish() {
    if (m_fall_pending) fall_at(*m_last_rise_ps + kStepHighPs);
    m_scanned_ps = std::numeric_limits<TimePs>::max();
}

TimePs StepTrain::final_until_ps() const {
    // A pending fall comes after the last rise; the next step's DIR edge at most kDirLeadPs before its rise.
    if (m_fall_pending) return *m_last_rise_ps + 1;
    if (m_scanned_ps == std::numeric_limits<TimePs>::max()) return m_scanned_ps;
    return m_scanned_ps - kDirLeadPs;
}

std::vector<PinEdge> StepTrain::take() {
    return std::exchange(m_edges, {});
}

}  // namespace cnc::sim::ideal
