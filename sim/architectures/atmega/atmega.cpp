#include "architectures/atmega/atmega.hpp"

#include "architectures/atmega/atmega_settings.hpp"

namespace cnc::sim::atmega {

namespace {

class Atmega final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "atmega"; }
    // The head's pin follows the motion code (seed 003 App. A2-A4: pen up in G00, down in G01 and the arcs); the PC
    // program plans the job whole before it sends it.
    [[nodiscard]] JobUse job_use() const override { return {true, false, LaserSwitching::ByMotionKind, false}; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario&,
                                                                    const std::filesystem::path& base) const override {
        auto s = std::make_shared<AtmegaSettings>();
        read_atmega_settings(r, *s, base);
        return s;
    }

    // The link's wires, the CP2102's USB link, the host program, the DRV8825s on the machine's pins.
    [[nodiscard]] FaultLinks fault_links() const override { return serial_host_links(); }
    [[nodiscard]] std::string plot_colour() const override { return "#d55e00"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const Atmega a;
    return a;
}

}  // namespace cnc::sim::atmega
