#include "architectures/spi_fpga/spi_fpga.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "architectures/spi_fpga/spi_fpga_settings.hpp"
#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::sim::spi_fpga {

namespace {

constexpr double kSecondsPerMinute = 60.0;

class SpiFpga final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "spi-fpga"; }
    // The servo sets each frame's laser bit from the job; the planner reads the job again as the servo consumes it.
    [[nodiscard]] JobUse job_use() const override { return {true, false, LaserSwitching::FollowsJob, true}; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario& common,
                                                                    const std::filesystem::path& base) const override {
        auto s = std::make_shared<SpiFpgaSettings>();
        read_spi_fpga_settings(r, base, *s, common.machine);
        return s;
    }

    // The slowest step rate the rate word can set: one step per 2^30 - 1 clocks.
    void check_move(const std::string& where, const host::ProgrammedMove& m, const Scenario& s) const override {
        if (m.kind == host::MotionKind::Rapid) return;
        const double length_mm = m.path.length_mm();
        const double dx = std::fabs(m.path.end.x_mm - m.path.start.x_mm);
        const double dy = std::fabs(m.path.end.y_mm - m.path.start.y_mm);
        // The faster axis on a line; on an arc each axis passes through the full path speed.
        const double share_x = m.path.is_arc ? 1.0 : dx / length_mm;
        const double share_y = m.path.is_arc ? 1.0 : dy / length_mm;
        const double mm_per_s = m.feed_mm_per_min / kSecondsPerMinute;
        const double steps_per_s =
            mm_per_s * std::max(share_x * s.machine.x.steps_per_mm(), share_y * s.machine.y.steps_per_mm());
        const double slowest = spi::rate_for_period(spi::kMaxPeriodCycles, s.settings<SpiFpgaSettings>().fpga.clk_hz);
        if (steps_per_s < slowest) {
            throw BadInput(where, fmt::format(FMT_STRING("feed {:.6g} mm/min steps the leading axis {:.6g} times a "
                                                         "second, slower than the spi-fpga rate word's slowest step "
                                                         "(one per 2^30 - 1 clocks: {:.4g} steps/s at "
                                                         "fpga_spi.clock_hz); raise F"),
                                              m.feed_mm_per_min, steps_per_s, slowest));
        }
    }

    // The SPI wires, the DRV8825s on the machine's pins.
    [[nodiscard]] FaultLinks fault_links() const override {
        FaultLinks links;
        links.spi = true;
        links.step_input = true;
        return links;
    }
    [[nodiscard]] std::string plot_colour() const override { return "#009e73"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const SpiFpga a;
    return a;
}

}  // namespace cnc::sim::spi_fpga
