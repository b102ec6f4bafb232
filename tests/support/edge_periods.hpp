// The periods between consecutive edge times, for the tests that check a pulse train's spacing.
#pragma once
#include <cstddef>
#include <vector>

#include "common/units.hpp"

namespace cnc::test {

inline std::vector<TimePs> periods(const std::vector<TimePs>& t) {
    std::vector<TimePs> d;
    for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
    return d;
}

}  // namespace cnc::test
