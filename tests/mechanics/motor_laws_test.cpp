// The cited laws of the mechanics core, each against a number worked out here from the data sheet, the seed
// thesis or the physics (never read back from the code under test), at the edges where a changed constant,
// sign or comparison shows: the hybrid stepper's torque, back-EMF and detent; the DRV8825's set-points,
// bridge clamp and STEP/DIR timing limits at their exact boundary; the belt's stiffness and forces; the rail's
// stick band.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanics/core/axis_load.hpp"
#include "mechanics/core/drv8825_current.hpp"
#include "mechanics/core/drv8825_timing.hpp"
#include "mechanics/core/friction.hpp"
#include "mechanics/core/hybrid_stepper.hpp"

using cnc::TimePs;
using namespace cnc::mech;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNmPerGcm = 9.80665e-5;  // 1 g cm = 1e-3 kg x 9.80665 m/s2 x 1e-2 m
constexpr double kDeg = kPi / 180.0;

// Winding currents of the electrical angle `deg` at `amps` (the DRV8825 set-points are I cos, I sin).
WindingCurrents currents_at(double deg, double amps) {
    return {amps * std::cos(deg * kDeg), amps * std::sin(deg * kDeg)};
}

}  // namespace

// ---- Hybrid stepper (seed 000 §2.3: 42BYGHW208, 1.8 deg, 0.4 A/phase, 2,800 g cm) -------------------------

TEST(HybridStepperLaws, FullStepIs1point8DegOf50RotorTeeth) {
    // seed 000 §2.3: 1.8 deg per full step; 360 / (4 x 50 teeth) = 1.8.
    const HybridStepperParams p;
    EXPECT_NEAR(p.full_step_rad(), 1.8 * kDeg, 1e-15);
    // One full step is 90 electrical degrees: the rotor's electrical angle moves pi/2 from home (45 deg).
    EXPECT_NEAR(rotor_electrical_rad(p, 1.8 * kDeg) - rotor_electrical_rad(p, 0.0), kPi / 2, 1e-12);
    EXPECT_NEAR(rotor_electrical_rad(p, 0.0), 45.0 * kDeg, 1e-15);
}

TEST(HybridStepperLaws, HoldingTorqueIs2800GcmWithBothPhasesAtRatedCurrent) {
    // seed 000 §2.3 rates 2,800 g cm with both phases at 0.4 A. Both windings at +0.4 A make a field at 45 deg
    // electrical, the home rest angle; one full step behind it (rotor at -1.8 deg, psi = -45 deg) the load angle
    // is 90 electrical degrees, the peak of the torque-angle curve: 2,800 g cm, pulling the rotor forward (+).
    const HybridStepperParams p;
    const double km = p.torque_constant_nm_per_a();
    const WindingCurrents both_rated{0.4, 0.4};
    const double t_hold_nm = 2800.0 * kNmPerGcm;  // 0.27459 N m
    EXPECT_NEAR(electromagnetic_torque_nm(km, rotor_angle(p, -1.8 * kDeg), both_rated), t_hold_nm, 1e-12);
    EXPECT_NEAR(electromagnetic_torque_nm(km, rotor_angle(p, +1.8 * kDeg), both_rated), -t_hold_nm, 1e-12);
    EXPECT_NEAR(electromagnetic_torque_nm(km, rotor_angle(p, 0.0), both_rated), 0.0, 1e-15);  // at rest
    // A rotor a quarter of the way (0.45 deg, 22.5 electrical deg) behind: T_hold sin(22.5 deg).
    EXPECT_NEAR(electromagnetic_torque_nm(km, rotor_angle(p, -0.45 * kDeg), both_rated),
                t_hold_nm * std::sin(22.5 * kDeg), 1e-12);
}

TEST(HybridStepperLaws, TorqueAtAMicrostepSetPointBelowRatedCurrent) {
    // At 0.3 A along microstep k = 5 of 1/32 (45 + 5 x 2.8125 = 59.0625 electrical deg), the vector is 0.3 A, not
    // 0.3 sqrt(2): its peak torque is 2,800 g cm x 0.3 / (sqrt(2) x 0.4). Rotor at home (psi = 45 deg): load
    // angle 14.0625 deg ahead, the torque pulls forward.
    const HybridStepperParams p;
    const double km = p.torque_constant_nm_per_a();
    const double peak_nm = 2800.0 * kNmPerGcm * 0.3 / (std::sqrt(2.0) * 0.4);
    EXPECT_NEAR(electromagnetic_torque_nm(km, rotor_angle(p, 0.0), currents_at(59.0625, 0.3)),
                peak_nm * std::sin(14.0625 * kDeg), 1e-12);
}

TEST(HybridStepperLaws, BackEmfPowerEqualsMechanicalPowerInEitherDirection) {
    // Energy conservation: the power the windings deliver against their back-EMF, e_a i_a + e_b i_b, is the
    // mechanical power T omega, for any angle, current and speed (a wrong sign of e_a or e_b breaks it).
    // Its amplitude is K_m omega: 2,800 g cm / (sqrt(2) x 0.4 A) = 0.4854 V s/rad.
    const HybridStepperParams p;
    const double km = p.torque_constant_nm_per_a();
    const double km_expected = 2800.0 * kNmPerGcm / (std::sqrt(2.0) * 0.4);
    for (double theta_deg : {-0.7, 0.0, 0.31, 1.3, 7.9}) {
        for (double omega : {-25.0, 3.0, 40.0}) {
            const RotorAngle a = rotor_angle(p, theta_deg * kDeg);
            const WindingCurrents i{0.17, -0.31};
            const WindingCurrents e = back_emf_v(km, a, omega);
            const double p_electrical_w = e.a_a * i.a_a + e.b_a * i.b_a;
            const double p_mechanical_w = electromagnetic_torque_nm(km, a, i) * omega;
            EXPECT_NEAR(p_electrical_w, p_mechanical_w, 1e-12) << theta_deg << " deg, " << omega << " rad/s";
            EXPECT_NEAR(std::hypot(e.a_a, e.b_a), km_expected * std::abs(omega), 1e-12);
        }
    }
    // At home (psi = 45 deg) turning forward, e_a = -K_m w sin 45 < 0 and e_b = +K_m w cos 45 > 0.
    const WindingCurrents e_home = back_emf_v(km, rotor_angle(p, 0.0), 10.0);
    EXPECT_NEAR(e_home.a_a, -km_expected * 10.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(e_home.b_a, +km_expected * 10.0 / std::sqrt(2.0), 1e-12);
}

TEST(HybridStepperLaws, DetentHasOnePeriodPerFullStepAndPullsTowardsItsMinima) {
    // Detent -T_det sin(4 N_r theta): one period per 1.8 deg full step, restoring towards theta = 0 (a detent
    // minimum, where its energy is zero). At a quarter of a full step (0.45 deg, 4 N_r theta = 90 deg) it is
    // -T_det; at 3/4 (1.35 deg) +T_det; the torque is minus the slope of the energy.
    HybridStepperParams p;
    p.detent_torque_nm = 150.0 * kNmPerGcm;
    const double t_det = 150.0 * kNmPerGcm;
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, 0.45 * kDeg)), -t_det, 1e-12);
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, -0.45 * kDeg)), +t_det, 1e-12);
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, 1.35 * kDeg)), +t_det, 1e-12);
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, (0.45 + 1.8) * kDeg)), -t_det, 1e-12);  // the next step
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, 0.15 * kDeg)), -t_det * std::sin(30.0 * kDeg), 1e-12);
    EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, 0.9 * kDeg)), 0.0, 1e-12);  // half step: unstable point
    EXPECT_DOUBLE_EQ(detent_energy_j(p, 0.0), 0.0);
    EXPECT_NEAR(detent_energy_j(p, 0.9 * kDeg), 2.0 * t_det / 200.0, 1e-15);  // maximum T_det (1 - cos pi) / (4 N_r)
    for (double theta_deg : {0.1, 0.3, 1.0, -0.6}) {
        const double h = 1e-7;
        const double slope = (detent_energy_j(p, theta_deg * kDeg + h) - detent_energy_j(p, theta_deg * kDeg - h)) / (2 * h);
        EXPECT_NEAR(detent_torque_nm(p, rotor_angle(p, theta_deg * kDeg)), -slope, 1e-8) << theta_deg << " deg";
    }
}

// ---- DRV8825 current regulation (SLVSA73 §8.3.4, §8.3.2) ---------------------------------------------------

TEST(Drv8825CurrentLaws, SetPointsAreTheSineTableTimesTheLimitAndZeroWhenDisabled) {
    // §8.3.2 table: home 71 % / 71 %; 16 units (a half step) on: 90 deg, 0 % / 100 %; 48 units: 180 deg,
    // -100 % / 0 % (the negative direction of winding A); -16 units: 0 deg, 100 % / 0 %. At 0.4 A (seed 000 §2.3).
    DriverElectrics drv;
    drv.current_limit_a = 0.4;
    const WindingSetpoints home = winding_setpoints(0, drv, true);
    EXPECT_NEAR(home.a_a, 0.4 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(home.b_a, 0.4 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(winding_setpoints(16, drv, true).a_a, 0.0, 1e-12);
    EXPECT_NEAR(winding_setpoints(16, drv, true).b_a, 0.4, 1e-12);
    EXPECT_NEAR(winding_setpoints(48, drv, true).a_a, -0.4, 1e-12);
    EXPECT_NEAR(winding_setpoints(-16, drv, true).a_a, 0.4, 1e-12);
    EXPECT_NEAR(winding_setpoints(-16, drv, true).b_a, 0.0, 1e-12);
    // nENBL high: no current, no holding torque.
    const WindingSetpoints off = winding_setpoints(0, drv, false);
    EXPECT_EQ(off.a_a, 0.0);
    EXPECT_EQ(off.b_a, 0.0);
}

TEST(Drv8825CurrentLaws, BridgeSettlesTheCurrentAtRPlusLOverTauAndClampsAtVmot) {
    // Circuit law of a winding: L di/dt = V - R i - e. With the bridge voltage R i_ref + e + (L/tau)(i_ref - i)
    // this is L di/dt = -(R + L/tau)(i - i_ref): the error decays at R/L + 1/tau whatever the back-EMF.
    // 30 ohm, 37 mH (Wantai listing), tau 20 us: 810.8 + 50,000 = 50,810.8 /s.
    DriverElectrics drv;
    drv.supply_v = 12.0;  // seed 000 §2.3 VMOT
    drv.chop_tau_s = 20e-6;
    const double r = 30.0;
    const double l = 0.037;
    EXPECT_NEAR(regulation_rate_per_s(r, l, drv), 30.0 / 0.037 + 1.0 / 20e-6, 1e-9);
    // Small error, a back-EMF of -2 V: the bridge regulates, and di/dt is -rate x error.
    const double i_ref = 0.20;
    const double i = 0.1999;
    const double e = -2.0;
    const double v = bridge_voltage_v(i_ref, i, e, r, l, drv);
    const double di_dt = (v - r * i - e) / l;
    EXPECT_NEAR(di_dt, -(30.0 / 0.037 + 1.0 / 20e-6) * (i - i_ref), 1e-6);
    // A large step up asks for more than VMOT: +12 V; down: -12 V (fast decay reverses the bridge).
    EXPECT_DOUBLE_EQ(bridge_voltage_v(0.4, 0.0, 0.0, r, l, drv), 12.0);
    EXPECT_DOUBLE_EQ(bridge_voltage_v(-0.4, 0.0, 0.0, r, l, drv), -12.0);
    // 11.9 V wanted (0.3 A, no back-EMF, at the set-point: R i = 9 V, plus 2.9 V of EMF) is within VMOT.
    EXPECT_NEAR(bridge_voltage_v(0.3, 0.3, 2.9, r, l, drv), 11.9, 1e-12);
}

// ---- DRV8825 STEP/DIR timing (SLVSA73 §7.6: tWH, tWL 1.9 us; tSU, tH 650 ns) at the exact limit --------------

TEST(Drv8825TimingLaws, StepHighAndLowOf1900NsPassAnd1899999PsFail) {
    // SLVSA73 §7.6: STEP high and low at least 1.9 us. Exactly the minimum is legal; one picosecond less is not.
    Drv8825TimingChecker ok;
    ok.on_step(10'000'000, true);
    ok.on_step(10'000'000 + 1'900'000, false);                // high 1.9 us
    ok.on_step(10'000'000 + 3'800'000, true);                 // low 1.9 us (period 3.8 us: rate apart)
    ok.on_step(10'000'000 + 5'700'000, false);
    EXPECT_EQ(ok.stats()[TimingRule::StepHigh].violations, 0);
    EXPECT_EQ(ok.stats()[TimingRule::StepLow].violations, 0);
    Drv8825TimingChecker short_high;
    short_high.on_step(10'000'000, true);
    short_high.on_step(10'000'000 + 1'899'999, false);
    EXPECT_EQ(short_high.stats()[TimingRule::StepHigh].violations, 1);
    EXPECT_EQ(short_high.stats()[TimingRule::StepHigh].worst_ps, 1'899'999);
    Drv8825TimingChecker short_low;
    short_low.on_step(10'000'000, true);
    short_low.on_step(12'000'000, false);
    short_low.on_step(12'000'000 + 1'899'999, true);
    EXPECT_EQ(short_low.stats()[TimingRule::StepLow].violations, 1);
    EXPECT_EQ(short_low.stats()[TimingRule::StepLow].worst_ps, 1'899'999);
}

TEST(Drv8825TimingLaws, DirSetupAndHoldOf650NsPassAnd649999PsFail) {
    // SLVSA73 §7.6: DIR stable 650 ns before (tSU) and after (tH) the STEP rise.
    Drv8825TimingChecker ok;
    ok.on_dir(10'000'000 - 650'000, true);  // setup exactly 650 ns
    ok.on_step(10'000'000, true);
    ok.on_dir(10'000'000 + 650'000, false);  // hold exactly 650 ns
    ok.on_step(10'000'000 + 2'000'000, false);
    EXPECT_EQ(ok.stats()[TimingRule::DirSetup].violations, 0);
    EXPECT_EQ(ok.stats()[TimingRule::DirSetup].checks, 1);
    EXPECT_EQ(ok.stats()[TimingRule::DirHold].violations, 0);
    EXPECT_EQ(ok.stats()[TimingRule::DirHold].checks, 1);
    Drv8825TimingChecker bad;
    bad.on_dir(10'000'000 - 649'999, true);
    bad.on_step(10'000'000, true);
    bad.on_dir(10'000'000 + 649'999, false);
    EXPECT_EQ(bad.stats()[TimingRule::DirSetup].violations, 1);
    EXPECT_EQ(bad.stats()[TimingRule::DirSetup].worst_ps, 649'999);
    EXPECT_EQ(bad.stats()[TimingRule::DirHold].violations, 1);
    EXPECT_EQ(bad.stats()[TimingRule::DirHold].worst_ps, 649'999);
}

TEST(Drv8825TimingLaws, StepRateOf250KHzPassesAndOnePsFasterFails) {
    // SLVSA73 §7.6: fSTEP at most 250 kHz, a rise-to-rise period of 4 us. 3.999999 us is faster.
    Drv8825TimingChecker c;
    c.on_step(0, true);
    c.on_step(1'900'000, false);
    c.on_step(4'000'000, true);  // 250 kHz exactly: allowed
    c.on_step(5'900'000, false);
    c.on_step(4'000'000 + 3'999'999, true);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].checks, 2);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].first_violation_ps, 7'999'999);
}

// ---- Belt and rails (seed 000 §3.4.2 GT2 x 20 = 40 mm/rev; §7.1.2 spans) --------------------------------------

TEST(BeltLaws, StiffnessIsTwoSpansInParallel) {
    // k(x) = c/L1 + c/L2, L1 = home span + x, L2 = total - L1; c = 20,000 N, home 50 mm, total 560 mm.
    // x = 0: 20,000/0.05 + 20,000/0.51 = 439,215.7 N/m (stiff near the motor); x = 460 mm (the far end of
    // seed 000's travel): L1 = 0.51, L2 = 0.05, the same; x = 230 mm: 20,000/0.28 x 2 = 142,857.1 N/m.
    AxisLoadParams p;
    p.belt_specific_stiffness_n = 20'000.0;
    p.belt_home_span_mm = 50.0;
    p.belt_total_span_mm = 560.0;
    const Coupling belt(p);
    EXPECT_NEAR(belt.belt_stiffness_n_per_m(0.0), 20'000.0 / 0.05 + 20'000.0 / 0.51, 1e-6);
    EXPECT_NEAR(belt.belt_stiffness_n_per_m(0.460), 20'000.0 / 0.51 + 20'000.0 / 0.05, 1e-6);
    EXPECT_NEAR(belt.belt_stiffness_n_per_m(0.230), 2 * 20'000.0 / 0.28, 1e-6);
}

TEST(BeltLaws, ForcesAreMinusTheGradientOfTheStoredEnergy) {
    // U = k(x) (r theta - x)^2 / 2 with r = 40 mm / 2 pi: F_carriage = -dU/dx, T_rotor = -dU/dtheta. The dk/dx
    // term matters near a short span: carriage at 5 mm (L1 = 55 mm), belt stretched +0.2 mm and -0.2 mm.
    AxisLoadParams p;
    p.belt_damping_ratio = 0.0;  // at rest the damping adds nothing anyway; keep the forces conservative
    const Coupling belt(p);
    const double r_m = 0.040 / (2 * kPi);
    EXPECT_NEAR(travel_m_per_rad(p), r_m, 1e-15);
    for (double stretch_m : {0.2e-3, -0.2e-3}) {
        const double x = 0.005;
        const double theta = (x + stretch_m) / r_m;
        const CouplingForces f = belt.forces(theta, 0.0, x, 0.0);
        const double hx = 1e-7;
        const double ht = hx / r_m;
        const double du_dx = (belt.energy_j(theta, x + hx) - belt.energy_j(theta, x - hx)) / (2 * hx);
        const double du_dt = (belt.energy_j(theta + ht, x) - belt.energy_j(theta - ht, x)) / (2 * ht);
        EXPECT_NEAR(f.on_carriage_n, -du_dx, 1e-5 * std::abs(du_dx)) << stretch_m;
        EXPECT_NEAR(f.on_rotor_nm, -du_dt, 1e-5 * std::abs(du_dt)) << stretch_m;
        // The pulley ahead of the carriage pulls it forward (+x) and holds the rotor back.
        EXPECT_EQ(f.on_carriage_n > 0, stretch_m > 0);
        EXPECT_EQ(f.on_rotor_nm < 0, stretch_m > 0);
    }
}

TEST(RailFrictionLaws, OpposesMotionAndSticksOnlyBelowTheBand) {
    // Karnopp's model with a 0.1 mm/s band: at the band edge the carriage slides (full -F_c); just inside it
    // friction cancels the other forces up to F_c (static friction) and brakes the speed to 0 in 1 ms.
    AxisLoadParams p;
    p.rail_friction_n = 1.5;
    p.rail_viscous_n_per_m_s = 0.0;
    p.carriage_mass_kg = 3.8;  // seed 000 §2.3
    EXPECT_DOUBLE_EQ(rail_friction_n(p, +2e-3, 0.0), -1.5);
    EXPECT_DOUBLE_EQ(rail_friction_n(p, -2e-3, 0.0), +1.5);
    EXPECT_DOUBLE_EQ(rail_friction_n(p, +1e-4, 0.0), -1.5);  // exactly at the band: sliding
    EXPECT_DOUBLE_EQ(rail_friction_n(p, -1e-4, 0.0), +1.5);
    EXPECT_EQ(friction_mode(0.99e-4, 1e-4), FrictionMode::Stuck);
    EXPECT_DOUBLE_EQ(rail_friction_n(p, 0.0, 1.0), -1.0);   // holds a 1 N push
    EXPECT_DOUBLE_EQ(rail_friction_n(p, 0.0, -2.0), 1.5);   // but not a 2 N pull: at most F_c
    // Stuck at 0.05 mm/s with no other force: -m v / 1 ms = -3.8 x 5e-5 / 1e-3 = -0.19 N.
    EXPECT_NEAR(rail_friction_n(p, 5e-5, 0.0), -0.19, 1e-12);
}
