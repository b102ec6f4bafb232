// The firmware's B(n) list for a pitch (seed 002 §2.1-2.2, §2.5.3), built by the same C code the firmware runs
// (models/avr/firmware/lathe_sync/ratio_list.c), with what it means for the thread: the ratio it realises and
// the pitch that ratio cuts.
#pragma once
#include <cstdint>
#include <vector>

namespace cnc::lathe {

enum class MakelistMode {
    Intended,   // the smallest |residual| for a denominator <= 150 (§2.2's final procedure)
    AsPrinted,  // the listing's search with its int32/uint32 defects (as §2.5.3 prints it)
};

// The seed's uint8 list entries cap lambda at 255 motor pulses per spindle pulse: ceil(39 P / 635) <= 255 for a
// pitch P in 0.01 mm (lambda = 39 P / 635 from the constants of §2.5.3) holds up to P = 4151, 41.51 mm.
inline constexpr int kMaxPitchCentiMm = 4151;

struct RatioList {
    int pitch_centi_mm = 0;
    std::uint16_t num = 0;           // motor pulses per list period (bestx)
    std::uint16_t den = 0;           // list length in spindle pulses (besty)
    std::vector<std::uint8_t> b;     // B(1) .. B(den), as the firmware stores them (uint8)
    double lambda_exact = 0.0;       // motor pulses per spindle pulse the pitch asks for
    double lambda_list = 0.0;        // what the list gives: sum(b) / den
    double lambda_error = 0.0;       // lambda_list - lambda_exact
    double pitch_produced_mm = 0.0;  // the pitch the list cuts
};

// pitch_centi_mm in 1 .. 65535 (the firmware's uint16 entry); the list is built whatever the pitch, as the
// firmware would (entries above 255 wrap): callers refuse pitches above kMaxPitchCentiMm.
[[nodiscard]] RatioList make_ratio_list(int pitch_centi_mm, MakelistMode mode);

}  // namespace cnc::lathe
