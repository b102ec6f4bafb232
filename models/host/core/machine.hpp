// Machine model of seed 000 §3.2 (AddModel "Machine Model Configuration"): per-axis motor, driver and
// transmission, and the steps/mm that the CAM and the NUMERATOR are derived from.
#pragma once
#include <optional>
#include <string>

namespace cnc::host {

enum class Transmission { Belt, Leadscrew };

// What an axis can do (LinuxCNC's [JOINT] MAX_VELOCITY, MAX_ACCELERATION): every architecture holds its moves to
// the velocity limit; an architecture that accelerates (the spi-fpga planner) also honours the others.
struct AxisLimits {
    double max_velocity_mm_per_s = 100.0;
    double max_accel_mm_per_s2 = 1000.0;
    double max_jerk_mm_per_s3 = 50000.0;  // jerk-limited profiles only
};

struct AxisMachine {
    double step_angle_deg = 1.8;  // seed 000 §3.4.2 T3.4: NEMA17 42BYGHW208, 200 full steps/rev
    int microsteps = 32;          // seed 000 T3.4: DRV8825 at 1/32
    Transmission transmission = Transmission::Belt;
    int pulley_teeth = 20;       // seed 000 T3.4: GT2 20T pulley
    double belt_pitch_mm = 2.0;  // seed 000 T3.4: GT2, 2 mm/tooth
    double lead_mm = 8.0;        // leadscrew only; 8 mm is the common T8 screw (seed 000 gives no leadscrew values)
    int screw_starts = 1;        // leadscrew only; travel_per_rev = lead x starts (seed 000 §3.4.2: belts only)
    double gear_ratio = 1.0;     // motor revs per pulley/screw rev (seed 000 §3.4.2; not on its AddModel form)
    double travel_mm = 0.0;      // TravelDistance of seed 000 §3.2; 0 = unlimited
    // A measured steps/mm (grbl's $100) that replaces the transmission's: machines are often calibrated, not
    // specified. It counts microsteps at `microsteps`, which still straps the DRV8825 MODE pins, so the motor
    // makes calibrated_steps_per_mm / microsteps full steps per mm.
    std::optional<double> calibrated_steps_per_mm;
    AxisLimits limits;

    [[nodiscard]] double steps_per_rev() const { return 360.0 / step_angle_deg * microsteps; }
    [[nodiscard]] double travel_per_rev_mm() const;
    // seed 000 §3.4.2: steps_per_rev * gear_ratio / travel_per_rev (160 for the defaults), whatever is calibrated.
    [[nodiscard]] double transmission_steps_per_mm() const;
    // The steps/mm every model uses: the calibrated value when there is one, else the transmission's.
    [[nodiscard]] double steps_per_mm() const;
    [[nodiscard]] double mm_per_step() const { return 1.0 / steps_per_mm(); }
    // Carriage travel per motor revolution that gives steps_per_mm(): what the mechanics model moves.
    [[nodiscard]] double travel_per_motor_rev_mm() const { return steps_per_rev() / steps_per_mm(); }
};

// The farthest an axis may be from 0, in microsteps: 2^30 - 1, so that any move between two positions is at most
// 2^31 - 2 steps, within the int32 step counts of the fpga-uart packet (seed 000 §4.8) and the spi-fpga FPGA's
// 32-bit step counters. At 160 steps/mm that is 6,710,886 mm; no machine has such a travel.
inline constexpr double kMaxPositionSteps = 1073741823.0;

struct MachineModel {
    AxisMachine x;
    AxisMachine y;
    // The third axis: no architecture of the seeds has Z STEP pins, so Z moves are host waits (gcode.hpp), timed
    // within z's velocity limit.
    AxisMachine z;
    bool soft_limits = true;  // keep the tool within each axis' travel (grbl $20; soft_limits.hpp)
};

// Throws cnc::BadInput(where, ...) for a value no machine can have, naming what is allowed.
// Microsteps must be one of the DRV8825 modes 1, 2, 4, 8, 16, 32 (seed 000 §2.3; the AddModel form of §3.2 offers
// only 8, 16 and 32, but the driver supports all six).
void validate(const AxisMachine& axis, const std::string& where);

// The path speed at which a straight displacement (dx, dy) keeps every axis within its velocity limit: `feed`
// itself when it does, less otherwise (mm/min in, mm/min out).
[[nodiscard]] double feed_within_axis_limits(double dx_mm, double dy_mm, double feed_mm_per_min,
                                             const MachineModel& machine);
void validate(const MachineModel& machine, const std::string& where);

}  // namespace cnc::host
