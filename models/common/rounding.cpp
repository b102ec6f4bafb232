#include "common/rounding.hpp"

#include <cmath>

namespace cnc {

double rounded(double v, double per_unit) {
    return std::round(v * per_unit) / per_unit;
}

}  // namespace cnc
