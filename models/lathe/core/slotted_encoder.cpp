#include "lathe/core/slotted_encoder.hpp"

#include <cmath>

namespace cnc::lathe {

bool SlottedEncoder::y_at(double rev) const {
    const double pitches = rev * m_slots + m_phase_pitches;
    return pitches - std::floor(pitches) < 0.5;
}

}  // namespace cnc::lathe
