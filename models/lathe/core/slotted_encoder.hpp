// A slotted disc read by an opto-interrupter through one 74HC14 inverting Schmitt trigger (seed 002 §2.3): the
// 30-slot motor disc in the H21A1, the 40-slot spindle disc in the GP1S73P, the half-reflective index disc on
// the reflective opto. The opto's transistor conducts (pulls its output low) while a slot lets the light through;
// the 74HC14 inverts that, so the pin the MCU reads (1Y) is high while a slot is in the beam and falls as the
// slot's trailing edge leaves it. Slots and bars are equally wide (the index disc: half reflective, half black).
#pragma once

namespace cnc::lathe {

class SlottedEncoder {
public:
    // `slots` per revolution; at revolution 0 the disc is `phase_pitches` of a slot pitch past a slot's leading
    // edge (1Y rises there, falls half a pitch later).
    SlottedEncoder(double slots, double phase_pitches) : m_slots(slots), m_phase_pitches(phase_pitches) {}

    // The 74HC14 output 1Y with the disc at `rev` revolutions from the start.
    [[nodiscard]] bool y_at(double rev) const;

private:
    double m_slots;
    double m_phase_pitches;
};

}  // namespace cnc::lathe
