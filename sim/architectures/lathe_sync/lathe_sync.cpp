#include "architectures/lathe_sync/lathe_sync.hpp"

#include "architectures/lathe_sync/lathe_settings.hpp"

namespace cnc::sim::lathe_sync {

namespace {

class LatheSync final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "lathe-sync"; }
    // No job and no laser: the operator's keys drive the lathe (its laser switching is never asked).
    [[nodiscard]] JobUse job_use() const override { return {false, false, LaserSwitching::FollowsJob, false}; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario&,
                                                                    const std::filesystem::path&) const override {
        auto s = std::make_shared<LatheSettings>();
        read_lathe_settings(r, *s);
        return s;
    }

    [[nodiscard]] std::string plot_colour() const override { return "#cc79a7"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const LatheSync a;
    return a;
}

}  // namespace cnc::sim::lathe_sync
