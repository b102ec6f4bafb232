// How seed 003's alignment (§5.1.2) and G-code generation (§5.1.3) tell that two points are the same: its Entity
// class keeps coordinates as float and compares them with ==; with a tolerance, within that distance (our fix).
#pragma once
#include <optional>

#include "common/geometry.hpp"

namespace cnc::cam {

struct Seed003Same {
    std::optional<double> tolerance_mm;
    bool operator()(geom::Vec2 a, geom::Vec2 b) const {
        if (tolerance_mm) return geom::distance(a, b) <= *tolerance_mm;
        return static_cast<float>(a.x_mm) == static_cast<float>(b.x_mm) &&
               static_cast<float>(a.y_mm) == static_cast<float>(b.y_mm);
    }
};

}  // namespace cnc::cam
