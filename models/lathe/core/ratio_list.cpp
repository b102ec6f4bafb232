#include "lathe/core/ratio_list.hpp"

#include <numeric>
#include <stdexcept>

#include "ratio_list.h"

namespace cnc::lathe {

RatioList make_ratio_list(int pitch_centi_mm, MakelistMode mode) {
    if (pitch_centi_mm < 1 || pitch_centi_mm > 65535) {
        throw std::invalid_argument("pitch must be 1 .. 65535 hundredths of a mm");
    }
    const auto pitch = static_cast<std::uint16_t>(pitch_centi_mm);
    const ratio_fraction f = mode == MakelistMode::Intended ? ratio_best(pitch) : ratio_best_as_printed(pitch);
    RatioList list;
    list.pitch_centi_mm = pitch_centi_mm;
    list.num = f.num;
    list.den = f.den;
    std::uint16_t rem = 0;
    for (int n = 0; n < f.den; ++n) list.b.push_back(ratio_next(&rem, f.num, f.den));
    list.lambda_exact = static_cast<double>(ratio_x(pitch)) / static_cast<double>(ratio_y());
    const int sum = std::accumulate(list.b.begin(), list.b.end(), 0);
    list.lambda_list = f.den > 0 ? static_cast<double>(sum) / f.den : 0.0;
    list.lambda_error = list.lambda_list - list.lambda_exact;
    list.pitch_produced_mm = pitch_centi_mm * 0.01 * list.lambda_list / list.lambda_exact;
    return list;
}

}  // namespace cnc::lathe
