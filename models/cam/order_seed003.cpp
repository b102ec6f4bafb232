// seed 003 §5.1.2 (App. A1, dated 02/02/2021): the alignment loop of CAD2G.
#include "cam/ordering.hpp"
#include "cam/seed003_compare.hpp"

#include <utility>

namespace cnc::cam {

namespace {

constexpr int kMaxRevisions = 100;  // `while (flag == 1 && revisions < 100)`

}  // namespace

std::vector<Step> seed003_sequence(const std::vector<Entity>& entities, const std::optional<double>& tolerance_mm) {
    const Seed003Same same{tolerance_mm};
    std::vector<Step> e;
    for (std::size_t i = 0; i < entities.size(); ++i) e.push_back({static_cast<int>(i), false});
    const auto start = [&](std::size_t i) { return step_path(entities, e[i]).start; };
    const auto end = [&](std::size_t i) { return step_path(entities, e[i]).end; };
    const std::size_t n = e.size();
    bool flag = true;
    for (int revisions = 0; flag && revisions < kMaxRevisions; ++revisions) {
        flag = false;
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                if (same(end(k), end(j))) {  // case 1: k runs into j's end: reverse k
                    e[k].reversed = !e[k].reversed;
                    flag = true;
                } else if (same(start(k), start(j))) {  // case 2: reverse k and put it before j
                    e[k].reversed = !e[k].reversed;
                    std::swap(e[j], e[k]);
                    flag = true;
                } else if (same(start(j), end(k))) {  // case 3 (the code's, not the prose's): k ends where j starts
                    std::swap(e[j], e[k]);
                    flag = true;
                }
            }
        }
        if (!flag) break;
        // The chain pass: the entity that starts where E[j] ends is brought next to it.
        for (std::size_t j = 0; j + 1 < n; ++j) {
            if (same(start(j + 1), end(j))) continue;
            for (std::size_t k = j + 2; k < n; ++k) {
                if (same(start(k), end(j))) {
                    std::swap(e[j + 1], e[k]);
                    break;
                }
            }
        }
    }
    return e;
}

}  // namespace cnc::cam
