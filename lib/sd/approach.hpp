// Normal approach of two particles under an external force (Rognon & Gay, Fig. 3): integration of the Soft
// Dynamics of one pair, eqs. (7) and (9), with GSL's ODE steppers, from h0 down to h_min.
//
// State y = (X, h) as in the paper (Fig. 4: "by integration, new values for h and X are obtained"). The
// deflection delta = (2R + h - X)/2 (eq. 2) is a small difference of large numbers whenever delta << h, so
// the adaptive error control asks for a relative accuracy `tolerance` on h and on delta (not on X, whose
// relative error says nothing about delta), down to the round-off floor 8 eps |X| of X itself.
//
// Samples are taken at nearly uniform steps of ln h (output times predicted from the current rate), so that
// the local exponents d ln delta / d ln h and d ln|h-dot| / d ln h are measured on an even grid.
#pragma once

#include "sd/contact_laws.hpp"
#include "sd/pair_dynamics.hpp"

#include <string>
#include <vector>

namespace softgrain::sd {

struct Stepper
{
    std::string name; // GSL name: rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf
    bool implicit;
    int index; // position in gsl_steppers(), for tables
};
const std::vector<Stepper>& gsl_steppers();
const Stepper& find_stepper(const std::string& name); // InputError listing the known names

struct ApproachProblem
{
    Material material;
    ContactLaws laws;
    Loading loading;
    double h0 = 100.0;   // initial gap (m)
    double h_min = 1e-6; // the run stops when h reaches h_min (m)
};

struct IntegratorSettings
{
    std::string stepper = "rk8pd";
    double tolerance = 1e-10;       // adaptive: relative local error of h and delta per step
    bool fixed_step = false;        // fixed: every step has size dt (no error control)
    double dt = 0;                  // fixed step (s)
    double samples_per_decade = 20; // output density in ln h
    long max_steps = 50'000'000;    // a guard against a stalled run
};

struct ApproachSample
{
    double t, X, h, F_ext;
    PairRates rates; // delta, a, zeta, C, D, F_ela, h_dot, X_dot at (X, h)
};

struct ApproachRun
{
    std::vector<ApproachSample> samples;
    long steps = 0;
    long rhs_evaluations = 0; // including those of finite-difference Jacobians
    double dt_lambda_max = 0; // fixed step only: max of dt |d h-dot/dh| along the run
};

// Starts from the balanced state: delta0 solves eq. (1) at h0 and X0 = 2R + h0 - 2 delta0 (eq. 2), so that no
// impulsive dF/dt is needed. Throws NumericalError (h <= 0, non-finite state, a fixed step that lets h grow
// under a compressive load: the explicit stability limit, with dt |d h-dot/dh| in the message; no progress).
ApproachRun integrate_approach(const ApproachProblem& problem, const IntegratorSettings& settings);

// d h-dot/dh along the balanced manifold delta = delta_eq(h) (1/s): the rate of the one non-trivial mode of
// the pair (the other is the neutral force-balance mode). An explicit step is stable for dt |.| below a bound
// of order 2-3 (2.785 for classical RK4).
double gap_rate_derivative(const ApproachProblem& problem, double h, double t);

// The two relaxation rates of eqs. (7), (9) at a state: real parts of the eigenvalues of the 2x2 Jacobian
// d(X-dot, h-dot)/d(X, h) (central differences), multiplied by the time scale tau = h/|h-dot| of the gap. A
// stiff problem would show |rate| tau >> 1; for the paper's laws the measured values are -lambda2 (0 ... 3)
// and a near-zero one (the neutral force-balance mode), see verification/sd/stiffness.cpp.
struct ModeRates
{
    double fast; // the most negative real part times tau
    double slow; // the other one times tau
};
ModeRates jacobian_modes(const ApproachProblem& problem, double t, double X, double h);

// Reference for constant loading: the time to go from h0 to h, t(h) = int_h^h0 zeta(a(h', delta_eq(h')), h')
// / (F_ext - F_adh) dh' (eq. 7 with eq. 1 exactly satisfied), by GSL adaptive quadrature in ln h'.
double approach_time_reference(const ApproachProblem& problem, double h_from, double h_to);

} // namespace softgrain::sd
