// seed 003 §5.1.2 (App. A1, dated 02/02/2021): the alignment loop of CAD2G.
#include <utility>

#include "cam/ordering.hpp"
#include "cam/seed003_compare.hpp"

namespace cnc::cam {

namespace {

constexpr int kMaxRevisions = 100;  // `while (flag == 1 && revisions < 100)`

// An entity in its slot of the array, with its ends as it is now turned (the loop compares them O(n^2) times a
// revision).
struct Slot {
    Step step;
    geom::Vec2 start, end;

    void turn() {
        step.reversed = !step.reversed;
        std::swap(start, end);
    }
};

}  // namespace

std::vector<Step> seed003_sequence(const std::vector<Entity>& entities, const std::optional<double>& tolerance_mm) {
    const Seed003Same same{tolerance_mm};
    std::vector<Slot> e;
    for (std::size_t i = 0; i < entities.size(); ++i) {
        e.push_back({{static_cast<int>(i), false}, entities[i].path.start, entities[i].path.end});
    }
    const std::size_t n = e.size();
    bool flag = true;
    for (int revisions = 0; flag && revisions < kMaxRevisions; ++revisions) {
        flag = false;
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                if (same(e[k].end, e[j].end)) {  // case 1: k runs into j's end: reverse k
                    e[k].turn();
                    flag = true;
                } else if (same(e[k].start, e[j].start)) {  // case 2: reverse k and put it before j
                    e[k].turn();
                    std::swap(e[j], e[k]);
                    flag = true;
                } else if (same(e[j].start, e[k].end)) {  // case 3 (the code's, not the prose's): k ends where j starts
                    std::swap(e[j], e[k]);
                    flag = true;
                }
            }
        }
        if (!flag) break;
        // The chain pass: the entity that starts where E[j] ends is brought next to it.
        for (std::size_t j = 0; j + 1 < n; ++j) {
            if (same(e[j + 1].start, e[j].end)) continue;
            for (std::size_t k = j + 2; k < n; ++k) {
                if (same(e[k].start, e[j].end)) {
                    std::swap(e[j + 1], e[k]);
                    break;
                }
            }
        }
    }
    std::vector<Step> steps;
    for (const Slot& s : e) steps.push_back(s.step);
    return steps;
}

}  // namespace cnc::cam
