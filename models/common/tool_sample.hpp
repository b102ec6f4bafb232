// Where the tool (carriage) is at a time: what the mechanics record and the path metrics measure.
#pragma once
#include "common/geometry.hpp"
#include "common/units.hpp"

namespace cnc {

struct ToolSample {
    TimePs t_ps = 0;
    geom::Vec2 pos;
};

}  // namespace cnc
