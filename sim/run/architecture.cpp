#include "run/architecture.hpp"

#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"
#include "systems/atmega/atmega_system.hpp"
#include "systems/fpga_uart_system.hpp"
#include "systems/lathe/lathe_system.hpp"
#include "systems/spi_fpga/spi_fpga_system.hpp"

namespace cnc::sim {

namespace {

void read_fpga_uart(KeyReader& r, Scenario& s, const std::filesystem::path&) { read_fpga_settings(r, s.fpga); }

void read_atmega(KeyReader& r, Scenario& s, const std::filesystem::path& base) {
    read_atmega_settings(r, s.atmega, base);
}

void read_spi_fpga(KeyReader& r, Scenario& s, const std::filesystem::path& base) {
    read_spi_fpga_settings(r, s.spi_fpga, base);
    s.spi_fpga.planner.x = s.machine.x.limits;  // one machine for every architecture
    s.spi_fpga.planner.y = s.machine.y.limits;
}

void read_lathe(KeyReader& r, Scenario& s, const std::filesystem::path&) { read_lathe_settings(r, s.lathe); }

}  // namespace

const std::vector<Architecture>& architectures() {
    // The seed 000 FPGA and the seed 003 head switch the laser by motion code; the seed 004 frame carries the
    // job's laser bit. The seed 002 lathe runs no job (its laser switching is never asked). fpga-uart reads a G-code
    // job again as it sends it, spi-fpga as its servo consumes the plan; atmega plans it whole.
    static const std::vector<Architecture> list = {
        {"fpga-uart", read_fpga_uart, run_fpga_uart, true, LaserSwitching::ByMotionKind, true},
        {"atmega", read_atmega, run_atmega, true, LaserSwitching::ByMotionKind, false},
        {"spi-fpga", read_spi_fpga, run_spi_fpga, true, LaserSwitching::FollowsJob, true},
        {"lathe-sync", read_lathe, run_lathe_sync, false, LaserSwitching::FollowsJob, false},
    };
    return list;
}

std::vector<std::string> architecture_names() {
    std::vector<std::string> names;
    for (const Architecture& a : architectures()) names.emplace_back(a.name);
    return names;
}

std::string architecture_list() {
    std::string text;
    for (const Architecture& a : architectures()) text += (text.empty() ? "" : ", ") + std::string(a.name);
    return text;
}

const Architecture& find_architecture(const std::string& name, const std::string& where) {
    for (const Architecture& a : architectures()) {
        if (name == a.name) return a;
    }
    throw BadInput(where, "unknown architecture '" + name + "' (allowed: " + architecture_list() + ")");
}

}  // namespace cnc::sim
