// The XY carriage: each axis is a drive (an ideal motor on a rigid transmission, or a dynamic axis model);
// the tool position is sampled at every step of either axis (DESIGN.md §4: contour error is sampled at every
// step event) and, with sample_hz > 0, periodically in between for as long as an axis is not at rest (a
// dynamic carriage keeps moving between steps: it lags, rings and settles). At each sample the position goes
// to the real-valued signals carriage_x_mm / carriage_y_mm (what the VCD traces) when it has moved by more than
// kPositionSignalResolutionMm since the value they hold.
#pragma once
#include <systemc>
#include <vector>

#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "mechanics/core/carriage_drive.hpp"

namespace cnc::mech {

struct CarriageAxis {
    const sc_core::sc_event* step_event = nullptr;  // the axis driver's step_event()
    const CarriageDrive* drive = nullptr;
};

struct CarriageConfig {
    CarriageAxis x;
    CarriageAxis y;
    geom::Vec2 origin{};  // tool position (machine mm) with both shafts at 0 deg
    double sample_hz = 0.0;  // periodic samples while an axis moves; 0: at step events only
};

using ToolSample = cnc::ToolSample;

// 0.1 um: a hundredth of the finest microstep of the shipped machines (1/32 step on a 40 mm/rev belt,
// 6.25 um), well below what a contour error of um needs, and it keeps a carriage settling by nm from writing
// a VCD value at every sample.
inline constexpr double kPositionSignalResolutionMm = 1e-4;
// Written by the step and the periodic sample processes.
using PositionSignal = sc_core::sc_signal<double, sc_core::SC_MANY_WRITERS>;

class Carriage : public sc_core::sc_module {
public:
    Carriage(const sc_core::sc_module_name& name, const CarriageConfig& cfg);

    // Tool position now.
    [[nodiscard]] geom::Vec2 position() const;
    // One sample at t = 0, then one per time stamp at which either axis stepped: steps of X and Y at the
    // same instant give one sample (the later one overwrites), so a diagonal step is not seen as an L.
    [[nodiscard]] const std::vector<ToolSample>& samples() const { return m_samples; }
    // Hands over the samples taken before t_ps and forgets them, for metrics that measure as the run goes (a
    // sample at t_ps or later may still be overwritten by a step at its instant, so it stays).
    [[nodiscard]] std::vector<ToolSample> take_samples_before(TimePs t_ps);
    // The tool position in machine mm, per axis, updated at the samples (resolution above).
    [[nodiscard]] const PositionSignal& carriage_x_mm() const { return m_carriage_x_mm; }
    [[nodiscard]] const PositionSignal& carriage_y_mm() const { return m_carriage_y_mm; }

private:
    void start_of_simulation() override;
    void sample();
    void on_step();
    void on_period();

    CarriageConfig m_cfg;
    std::vector<ToolSample> m_samples;
    sc_core::sc_event m_period_ev;
    bool m_periodic_armed = false;
    PositionSignal m_carriage_x_mm;
    PositionSignal m_carriage_y_mm;
};

}  // namespace cnc::mech
