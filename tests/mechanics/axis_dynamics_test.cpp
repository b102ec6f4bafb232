// The physical axis model against analytic solutions: rest angles, the torque-angle curve, the belt's natural
// frequency, energy conservation and the leadscrew's backlash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "mechanics/core/dynamic_axis.hpp"

using namespace cnc;
using namespace cnc::mech;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The seed motor alone (no carriage), without detent and Coulomb friction, so that the static equilibrium
// is set by the windings only; extra viscous damping only shortens the settling (it has no static effect).
// 0.3 A keeps R x I (9 V) below VMOT (12 V), so the currents reach their set-points exactly.
AxisParams bare_rotor() {
    AxisParams p;
    p.load.kind = DriveKind::Free;
    p.motor.detent_torque_nm = 0.0;
    p.motor.coulomb_nm = 0.0;
    p.motor.viscous_nm_per_rad_s = 2e-3;
    p.driver.current_limit_a = 0.3;
    return p;
}

constexpr TimePs kSettlePs = 200 * kPsPerMs;

}  // namespace

TEST(AxisDynamics, RestsAtEachMicrostepAngleWithoutDetent) {
    // The set-points are I (cos phi, sin phi), phi = 45 deg + k x 2.8125 deg (SLVSA73 table), so
    // T_em = K_m I sin(phi - psi) vanishes (stably) at psi = phi: theta = k x 1.8 deg / 32 exactly.
    const AxisParams p = bare_rotor();
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const double full_step_deg = 1.8;
    for (int k = 0; k <= 32; ++k) {
        const TimePs t = k * kSettlePs;
        axis.on_microstep(t, k, 32);
        const double angle = axis.shaft_angle_deg(t + kSettlePs - 1);
        EXPECT_NEAR(angle, k * full_step_deg / 32.0, 1e-6 * full_step_deg) << "microstep " << k;
        EXPECT_TRUE(axis.integrator().at_rest()) << "microstep " << k;
    }
    EXPECT_EQ(axis.stats().lost_full_steps, 0);
}

TEST(AxisDynamics, ReportsTheMicrostepErrorOfTheDetentTorque) {
    // As above, with the 42BYGHW208 detent torque (150 g cm): the rest angle solves
    //   K_m I sin(phi - psi(theta)) = T_det sin(4 N_r theta)
    // which this test solves by bisection (independently of the integrator) and compares.
    AxisParams p = bare_rotor();
    p.motor.detent_torque_nm = 0.0147;
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const double km_i = p.motor.holding_torque_nm / (std::sqrt(2.0) * 0.4) * 0.3;
    const double n_r = 50.0;
    double worst_microsteps = 0.0;
    for (int k = 0; k <= 8; ++k) {
        const TimePs t = k * kSettlePs;
        axis.on_microstep(t, k, 32);
        const double got_rad = axis.shaft_angle_deg(t + kSettlePs - 1) * kPi / 180.0;
        const double ideal_rad = k * (kPi / 100.0) / 32.0;
        const double phi = kPi / 4 + k * (kPi / 2) / 32.0;
        auto balance = [&](double th) {
            return km_i * std::sin(phi - (n_r * th + kPi / 4)) - p.motor.detent_torque_nm * std::sin(4 * n_r * th);
        };
        double lo = ideal_rad - kPi / 400;  // the root lies within a quarter of a full step of the ideal angle
        double hi = ideal_rad + kPi / 400;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (balance(mid) > 0 ? lo : hi) = mid;
        }
        EXPECT_NEAR(got_rad, 0.5 * (lo + hi), 1e-8) << "microstep " << k;
        worst_microsteps = std::max(worst_microsteps, std::abs(got_rad - ideal_rad) / (kPi / 100.0 / 32.0));
    }
    std::printf("detent 150 g cm at 0.3 A: worst microstep position error %.3f microsteps (1/32)\n", worst_microsteps);
    EXPECT_GT(worst_microsteps, 0.01);  // the detent does move the rest angles
}

TEST(AxisDynamics, ExternalTorqueDisplacesAlongTheTorqueAngleCurve) {
    // T = T_hold sin(N_r dtheta) with T_hold = K_m I = 0.2746 / (sqrt(2) 0.4) x 0.3 = 0.14563 N m.
    // A torque of T_hold / 2 moves the rotor by asin(0.5) / 50 = 0.0104720 rad (0.6 deg) along it.
    const AxisParams p = bare_rotor();
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const double t_hold = 0.2746 / (std::sqrt(2.0) * 0.4) * 0.3;
    axis.set_external_torque(kSettlePs, 0.5 * t_hold);
    const double angle_rad = axis.shaft_angle_deg(2 * kSettlePs) * kPi / 180.0;
    const double expected = std::asin(0.5) / 50.0;
    EXPECT_NEAR(angle_rad, expected, 0.01 * expected);
}

TEST(AxisDynamics, ARotorThatMovedWhileDisabledSlipsWhenEnabledAgain) {
    // The driver ignores STEP while disabled, so the command holds at 0. A torque of 4.2 mN m against the 2e-3
    // N m s/rad damping turns the free rotor at 2.1 rad/s (time constant J / b = 1.7 ms) for 50 ms: about 6 deg,
    // 3.3 full steps, past the unstable equilibrium at 2 full steps (half an electrical period, 3.6 deg) and short
    // of the one after (10.8 deg). Enabled again, it is pulled into the next period: 4 full steps ahead of the
    // command (7.2 deg), counted at the enable.
    const AxisParams p = bare_rotor();
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    axis.on_enable(kSettlePs, false);
    axis.set_external_torque(kSettlePs, 4.2e-3);
    axis.set_external_torque(kSettlePs + 50 * kPsPerMs, 0.0);
    const TimePs enable_ps = 2 * kSettlePs;
    const double coasted_deg = axis.shaft_angle_deg(enable_ps);
    ASSERT_GT(coasted_deg, 2 * 1.8);
    ASSERT_LT(coasted_deg, 6 * 1.8);
    EXPECT_EQ(axis.stats().lost_full_steps, 0);  // nothing counted while disabled
    axis.on_enable(enable_ps, true);
    EXPECT_NEAR(axis.shaft_angle_deg(enable_ps + kSettlePs), 4 * 1.8, 1e-6 * 1.8);
    EXPECT_EQ(axis.stats().lost_full_steps, 4);
    ASSERT_EQ(axis.stats().events.size(), 1U);
    EXPECT_EQ(axis.stats().events[0].t_ps, enable_ps);
    EXPECT_EQ(axis.stats().events[0].full_steps, -4);  // ahead of the command
}

TEST(AxisDynamics, ARotorOnTheUnstableEquilibriumSlipsOnceNotToAndFro) {
    // The command is set 2 full steps and one microstep (182.8 electrical deg) ahead of the rotor while the driver
    // is off, then the driver comes on and single microsteps move the command to 177.2 deg and back, all at one
    // instant: the rotor, on the unstable equilibrium, has not slipped either way. Left there, it falls back by a
    // whole period, 4 full steps behind the command, counted once it is 45 deg past the unstable point.
    const AxisParams p = bare_rotor();
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    axis.on_enable(kSettlePs, false);
    const TimePs t = 2 * kSettlePs;
    axis.on_microstep(t, 65, 32);
    axis.on_enable(t, true);
    axis.on_microstep(t, 63, 32);
    axis.on_microstep(t, 65, 32);
    EXPECT_EQ(axis.stats().lost_full_steps, 0);
    EXPECT_NEAR(axis.shaft_angle_deg(t + kSettlePs), (65.0 / 32.0 - 4.0) * 1.8, 1e-6 * 1.8);
    EXPECT_EQ(axis.stats().lost_full_steps, 4);
    ASSERT_EQ(axis.stats().events.size(), 1U);
    EXPECT_EQ(axis.stats().events[0].full_steps, 4);  // behind the command
}

TEST(AxisDynamics, BeltCarriageRingsAtItsNaturalFrequency) {
    // Shaft held (rotor inertia 1000 kg m2 against a carriage reflecting 3.8 kg x (6.37 mm)^2),
    // no damping or friction, carriage at 200 mm released 10 um off the belt's neutral position.
    // k = c_sp / L1 + c_sp / L2 = 20000 / 0.25 + 20000 / 0.31 = 144516 N/m; f = sqrt(k / m) / 2 pi
    // = sqrt(144516 / 3.8) / 2 pi = 31.04 Hz.
    AxisParams p;
    p.motor.rotor_inertia_kgm2 = 1e3;
    p.motor.detent_torque_nm = 0.0;
    p.motor.coulomb_nm = 0.0;
    p.motor.viscous_nm_per_rad_s = 0.0;
    p.load.rail_friction_n = 0.0;
    p.load.belt_damping_ratio = 0.0;
    AxisIntegrator integ(p);
    const double x0 = 0.2;
    AxisState s = AxisState::Zero();
    s[kTheta] = x0 / travel_m_per_rad(p.load);
    s[kX] = x0 - 10e-6;
    integ.set_state(s);
    const double k = 20000.0 / 0.25 + 20000.0 / 0.31;
    const double f_expected = std::sqrt(k / 3.8) / (2 * kPi);
    std::vector<double> ups;
    double prev = integ.state()[kX] - x0;
    const double dt = 20e-6;
    for (int i = 1; i <= 25000; ++i) {
        integ.advance_to(i * dt);
        const double now = integ.state()[kX] - x0;
        if (prev < 0 && now >= 0) ups.push_back((i - 1) * dt + dt * (-prev) / (now - prev));
        prev = now;
    }
    ASSERT_GE(ups.size(), 10u);
    const double f = (ups.size() - 1) / (ups.back() - ups.front());
    EXPECT_NEAR(f, f_expected, 0.02 * f_expected);
}

TEST(AxisDynamics, ConservesEnergyWithoutDampingFrictionOrInput) {
    // Driver off (the currents stay 0: the bridge voltage equals the back-EMF, 0.49 V/(rad/s) x
    // 7.85 rad/s = 3.8 V < 12 V), no viscous, Coulomb, rail or belt losses; detent and belt are conservative.
    // Start: carriage and shaft at 50 mm/s (7.85 rad/s on the 6.366 mm pulley radius), belt stretched 20 um.
    // E = J w^2/2 + m v^2/2 + k(x) (r theta - x)^2/2 + T_det/(4 N_r) (1 - cos 4 N_r theta) stays constant.
    AxisParams p;
    p.motor.viscous_nm_per_rad_s = 0.0;
    p.motor.coulomb_nm = 0.0;
    p.load.rail_friction_n = 0.0;
    p.load.belt_damping_ratio = 0.0;
    AxisIntegrator integ(p, IntegratorTolerances{1e-12, 1e-11, 1e-3});
    AxisState s = AxisState::Zero();
    s[kV] = 0.05;
    s[kOmega] = 0.05 / travel_m_per_rad(p.load);
    s[kX] = -20e-6;
    integ.set_state(s);
    const double e0 = integ.ode().mechanical_energy_j(integ.state());
    integ.advance_to(1.0);
    const double e1 = integ.ode().mechanical_energy_j(integ.state());
    EXPECT_NEAR(e1, e0, 1e-6 * e0);
    EXPECT_GT(std::abs(integ.state()[kX]), 1e-3);  // the carriage did travel (the test is not at rest)
}

TEST(AxisDynamics, LeadscrewReversalHasADeadZoneOfTheBacklash) {
    // Tr8x8 screw (lead 8 mm), backlash 0.1 mm, 1 kg carriage, 5 N rail friction, 5e7 N/m axial
    // stiffness. Forward 1 mm and settle, then back 0.25 mm and settle: the screw turns through the play
    // before the nut pushes the carriage, so the carriage comes back by the screw's travel less the
    // backlash. The lost motion equals 0.1 mm within the two contact deflections (at most F / k = 5 N /
    // 5e7 N/m = 0.1 um each), the carriage's coasting into the play when the screw stops (v^2 / 2a with
    // the rotor's microstep ringing, ~1.3 mm/s peak at 0.5 mm/s, against 5 m/s2 of friction: 0.16 um) and
    // the integration tolerance (1e-8 m per step): 0.4 um in all.
    AxisParams p;
    p.load.kind = DriveKind::Leadscrew;
    p.load.travel_per_rev_mm = 8.0;
    p.load.backlash_mm = 0.1;
    p.load.carriage_mass_kg = 1.0;
    p.load.rail_friction_n = 5.0;
    p.load.screw_efficiency = 0.4;
    p.driver.current_limit_a = 0.3;
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const TimePs microstep_ps = kPsPerSec / 400;  // 400 microsteps/s = 0.5 mm/s
    const int one_mm = 800;                       // 6400 microsteps per 8 mm
    const int back = 200;                         // 0.25 mm
    for (int k = 1; k <= one_mm; ++k) axis.on_microstep(k * microstep_ps, k, 32);
    const TimePs reverse_ps = one_mm * microstep_ps + kSettlePs;
    const double mm_per_deg = 8.0 / 360.0;
    const double x1 = axis.carriage_mm(reverse_ps);
    const double s1 = axis.shaft_angle_deg(reverse_ps) * mm_per_deg;
    for (int k = 1; k <= back; ++k) axis.on_microstep(reverse_ps + k * microstep_ps, one_mm - k, 32);
    const TimePs end_ps = reverse_ps + back * microstep_ps + kSettlePs;
    const double x2 = axis.carriage_mm(end_ps);
    const double s2 = axis.shaft_angle_deg(end_ps) * mm_per_deg;
    EXPECT_NEAR((s1 - s2) - (x1 - x2), 0.1, 0.4e-3);
    // The shaft stops short of its command by the friction's load angle (0.018 N m against 0.146 N m: 2.4
    // microsteps) either way, and the detent moves rest angles by up to 1.9 microsteps each: at most
    // 2 x (2.4 + 1.9) = 8.6 microsteps of 1.25 um, 10.8 um.
    EXPECT_NEAR(x1 - x2, 0.25 - 0.1, 10.8e-3);
    EXPECT_EQ(axis.stats().lost_full_steps, 0);
}
