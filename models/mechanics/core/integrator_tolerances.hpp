// The error tolerances of an axis's integration (axis_integrator.hpp), apart from the integrator so that the
// scenario reads them without Boost.Odeint.
#pragma once

namespace cnc::mech {

struct IntegratorTolerances {
    double abs_tol = 1e-8;     // per step, in the state's SI units (A, rad, rad/s, m, m/s)
    double rel_tol = 1e-4;     // the reports change by < 0.03 um against 1e-5 (docs/mechanics.md)
    double max_step_s = 1e-3;  // never step further than this, so the step control sees every transient
};

}  // namespace cnc::mech
