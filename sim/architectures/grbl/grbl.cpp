#include "architectures/grbl/grbl.hpp"

#include "architectures/grbl/grbl_settings.hpp"
#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::grbl {

namespace {

// How to get the firmware this architecture runs: grbl's own source, built with Debian's avr-gcc.
constexpr const char* kHowToBuildGrbl =
    "the grbl architecture runs the firmware you give it as avr.firmware (an ELF or an Intel HEX file for the "
    "ATmega328P at 16 MHz, or the MCU avr.mcu names). grbl 1.1h: git clone https://github.com/gnea/grbl; cd grbl; "
    "make (it needs gcc-avr and avr-libc), then avr.firmware = \"path/to/grbl/grbl.hex\"";

class Grbl final : public Architecture {
public:
    [[nodiscard]] std::string name() const override { return "grbl"; }
    // grbl switches the laser as the job says (laser mode: on in G1/G2/G3 with M3/M4 and S, off in G0).
    [[nodiscard]] JobUse job_use() const override { return {true, false, LaserSwitching::FollowsJob, false}; }

    // It runs the firmware the user gives it: a column of `compare` when --arch names it.
    [[nodiscard]] bool compared_by_default() const override { return false; }

    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader& r, const Scenario&,
                                                                    const std::filesystem::path& base) const override {
        auto s = std::make_shared<GrblSettings>();
        read_grbl_settings(r, *s, base);
        return s;
    }

    void check_machine(const Scenario& s) const override {
        const GrblSettings& g = s.settings<GrblSettings>();
        if (g.board.firmware.empty()) throw BadInput(g.firmware_where, kHowToBuildGrbl);
        // grbl counts its machine position from where it powers up: the job's coordinates are that frame's.
        if (s.interpreter.start_mm.x_mm != 0.0 || s.interpreter.start_mm.y_mm != 0.0) {
            throw BadInput(s.file + ": scenario.start_x_mm, scenario.start_y_mm",
                           "grbl starts at its power-on position, machine 0,0: the job starts there too (leave "
                           "them 0 with the grbl architecture)");
        }
    }
    // Its moves are measured from the step pulses of straight blocks (step_windows.hpp); grbl cuts an arc into
    // segments of its own ($12) that the job does not know.
    void check_move(const std::string& where, const host::ProgrammedMove& move, const Scenario&) const override {
        if (move.kind == host::MotionKind::ArcCW || move.kind == host::MotionKind::ArcCCW) {
            throw BadInput(where,
                           "an arc (G2/G3): the grbl architecture measures straight moves only; give the job "
                           "its arcs as lines (a CAM's arc-to-line option)");
        }
    }

    // The link's wires, the CP2102's USB link, the host program, the DRV8825s on the machine's pins.
    [[nodiscard]] FaultLinks fault_links() const override { return serial_host_links(); }
    [[nodiscard]] std::string plot_colour() const override { return "#e69f00"; }
};

}  // namespace

const Architecture& Entry::architecture() {
    static const Grbl a;
    return a;
}

}  // namespace cnc::sim::grbl
