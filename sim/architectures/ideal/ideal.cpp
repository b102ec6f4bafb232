#include "architectures/ideal/ideal.hpp"

#include "architectures/ideal/ideal_settings.hpp"
#include "architectures/planner/planner_settings.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::ideal {

namespace {

class Ideal final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "ideal"; }
    // The laser follows the job's intent; the plan is read from the job as the run goes.
    [[nodiscard]] JobUse job_use() const override { return {true, false, LaserSwitching::FollowsJob, true}; }
    [[nodiscard]] bool baseline() const override { return true; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario& common,
                                                                    const std::filesystem::path&) const override {
        auto s = std::make_shared<IdealSettings>();
        read_planner_settings(r, common.machine, s->planner);
        return s;
    }

    // The DRV8825s on the machine's pins: it has no link.
    [[nodiscard]] FaultLinks fault_links() const override {
        FaultLinks links;
        links.step_input = true;
        return links;
    }
    [[nodiscard]] std::string plot_colour() const override { return "#000000"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const Ideal a;
    return a;
}

}  // namespace cnc::sim::ideal
