// How long the seed 003 firmware runs motion before it asks for the next byte, from the words the PC sends: the
// PC program's confirm timeout needs it (models/host/pc_program.hpp), since the next confirm after a start byte
// comes only when the motion lets the firmware go on.
//
// A counted axis makes its count of microsteps at one STEP period of 2 N (OCR + 1) cycles each (speed.hpp), so a
// motion lasts max(count_x x period(OCR0A), count_y x period(OCR2A)) cycles; count_y is sent by G00 only, and a
// dx = 0 motion counts |dy| on X's timer, which is what count_x and OCR0A then hold (timer1-y's G01: on Y's own
// timer, OCR1A).
#pragma once
#include <vector>

#include "host/core/cad2g/plan.hpp"

namespace cnc::host::cad2g {

// `x`: Timer0's clock; `y`: Y's (Plan::timer_y).
[[nodiscard]] double motion_s(const Motion& m, TimerClock x = {}, TimerClock y = {});

// Per transfer, the motion the firmware may still have to run after the transfer's last byte before it sends
// the next confirm (firmware commands.c, App. A2-A4):
//   G00 / G01: the motion its start byte starts (the Start loop confirms once it has ended);
//   arc chord k > 0: chord k - 1, which the firmware lets end before it loads chord k and asks for chord k + 1;
//   arc chord 0: nothing (it asks for chord 1 while chord 0 runs);
//   an arc's terminator: the last chord; M30: nothing (no byte follows it).
//   The clocks are the plan's (Plan::timer_x, Plan::timer_y).
[[nodiscard]] std::vector<double> motion_before_next_confirm_s(const Plan& plan,
                                                               const std::vector<Transfer>& transfers);

}  // namespace cnc::host::cad2g
