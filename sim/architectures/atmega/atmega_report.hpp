// The atmega section of the run report: the link at both ends (the CP2102's rate and the MCU's 58 823.5 Bd),
// the PC program's bytes and confirms, what happened between chords (late data: Y keeps stepping, seed 003
// §5.4.3), and with `detail` every command with its words and windows.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "architectures/atmega/chord_gaps.hpp"
#include "architectures/atmega/motion_windows.hpp"
#include "avr/avr_core.hpp"
#include "common/warning.hpp"
#include "host/core/cad2g/plan.hpp"
#include "host/pc_program.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

struct AtmegaFacts {
    const host::cad2g::Plan& plan;
    const host::MachineModel& machine;
    const host::PcProgram& pc;
    const uart::Cp2102& cp2102;
    const avr::AvrCore& mcu;
    const RecordLog<MotionWindow>& windows;  // read with `detail` only (kept whole then)
    const ChordGaps& gaps;
    std::string firmware;
    double mcu_baud = 0.0;  // f_cpu / (16 (UBRR0 + 1))
};

// Framing errors at either end, chords that started late.
[[nodiscard]] std::vector<Warning> link_warnings(const AtmegaFacts& f);
[[nodiscard]] nlohmann::json details_json(const AtmegaFacts& f, bool detail);
[[nodiscard]] std::string details_text(const AtmegaFacts& f);

}  // namespace cnc::sim
