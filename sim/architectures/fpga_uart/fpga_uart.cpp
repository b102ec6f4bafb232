#include "architectures/fpga_uart/fpga_uart.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "architectures/fpga_uart/fpga_uart_settings.hpp"
#include "common/bad_input.hpp"
#include "host/core/packet_codec.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::fpga_uart {

namespace {

// The model's message without its "machine: " place, which the scenario keys replace.
std::string numerator_problem(const BadInput& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

class FpgaUart final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "fpga-uart"; }
    // The FPGA switches the laser by motion code (laser_ctrl); the host reads a G-code job again as it sends it.
    [[nodiscard]] JobUse job_use() const override { return {true, true, LaserSwitching::ByMotionKind, true}; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario&,
                                                                    const std::filesystem::path& base) const override {
        auto s = std::make_shared<FpgaUartSettings>();
        read_fpga_uart_settings(r, base, *s);
        return s;
    }

    // The NUMERATOR of each axis (clock x 60 / steps per mm) must fit the init packet's uint32 (seed 000 §4.8).
    void check_machine(const Scenario& s) const override {
        const FpgaUartSettings& own = s.settings<FpgaUartSettings>();
        if (!own.numerator_from_machine) return;
        for (const auto& [axis, machine] : {std::pair{"x", &s.machine.x}, std::pair{"y", &s.machine.y}}) {
            try {
                (void)host::numerator(machine->steps_per_mm(), own.fpga.clk_hz);
            } catch (const BadInput& e) {
                const std::string p = std::string("machine.") + axis + ".";
                throw BadInput(s.file + ": " + p + "steps_per_mm (or " + p +
                                   "step_angle_deg, microsteps and the "
                                   "transmission keys), fpga.clock_hz",
                               fmt::format(FMT_STRING("{:.10g} steps/mm: "), machine->steps_per_mm()) +
                                   numerator_problem(e) +
                                   "; host.numerator = \"seed-constant\" sends the script's constant instead");
            }
        }
    }

    // The link's wires, the CP2102's USB link, the host program, the DRV8825s on the machine's pins.
    [[nodiscard]] FaultLinks fault_links() const override { return serial_host_links(); }
    // The e-stop and the lid's interlock are inputs of our FPGA when fpga.estop and fpga.interlock give it them.
    void check_events(const KeyReader& r, const std::vector<ScenarioEvent>& events,
                      const ArchSettings& settings) const override {
        const fpga::FpgaConfig& f = dynamic_cast<const FpgaUartSettings&>(settings).fpga;
        for (const ScenarioEvent& e : events) {
            if (e.input == SafetyInput::Estop && !f.estop_input) {
                r.fail(e.key, "the FPGA has no e-stop input: fpga.estop = true gives it one");
            }
            if (e.input == SafetyInput::Lid && !f.interlock_input) {
                r.fail(e.key, "the FPGA has no interlock input: fpga.interlock = true gives it one");
            }
        }
    }
    [[nodiscard]] std::string plot_colour() const override { return "#0072b2"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const FpgaUart a;
    return a;
}

}  // namespace cnc::sim::fpga_uart
