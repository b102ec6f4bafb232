#include "run/timed_progress.hpp"

#include <utility>

namespace cnc::sim {

TimedProgress::TimedProgress(std::ostream& out, ProgressStyle style, double expected_s, std::string label)
    : m_progress(out, style, expected_s, std::move(label)), m_start(std::chrono::steady_clock::now()) {}

double TimedProgress::wall_s() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

}  // namespace cnc::sim
