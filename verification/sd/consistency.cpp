// SD eqs. (1), (2), (9): along an integrated trajectory of (X, h), the deflection from eq. (2) keeps the
// force balance eq. (1), also under a time-dependent load (the -dF_ext/dt / C term of eq. 9), and h(t)
// matches the quadrature of eq. (7).
#include "core/errors.hpp"
#include "sd/approach.hpp"
#include "sd/approach_analysis.hpp"
#include "support/tolerance.hpp"

#include <cfloat>
#include <cmath>
#include <gsl/gsl_fit.h>
#include <string>
#include <vector>

using namespace softgrain::sd;
using softgrain::verification::Tolerance;

namespace {
const Material material{1.0, 1.0, 1.0, 4.0 / 9.0};
}

TEST_CASE("eq. (2) and force balance eq. (1) hold at every output to the solver tolerance [SD eqs. (1), (2), "
          "Fig. 4]")
{
    for (double kappa : {1e-6, 1e-3, 0.3})
        for (double tolerance : {1e-7, 1e-10}) {
            CAPTURE(kappa);
            CAPTURE(tolerance);
            const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa),
                                          100.0, 1e-6};
            IntegratorSettings settings;
            settings.tolerance = tolerance;
            const ApproachRun run = integrate_approach(problem, settings);
            const ApproachAnalysis a = analyse_approach(problem, run.samples, 0.1);
            for (std::size_t k = 0; k < run.samples.size(); ++k) {
                const ApproachSample& s = run.samples[k];
                // The force balance is a neutral invariant of eqs. (7), (9) (dF_ela/dt = dF_ext/dt
                // identically), so local errors of delta accumulate over the steps and are never damped.
                // Bound: the per-step relative tolerance on delta times the number of steps, plus the
                // round-off of delta = (2R + h - X)/2, 8 eps X/delta per step (the floor of the error
                // control), over the same steps.
                const double bound =
                    (tolerance + 8 * DBL_EPSILON * s.X / s.rates.delta) * static_cast<double>(run.steps);
                CAPTURE(s.h);
                CHECK(a.force_balance_residual[k] <= bound);
                CHECK(a.deflection_residual[k] <= bound);
            }
        }
}

TEST_CASE("a ramped force F(t) = F0 (1 + t/T) is followed: F_ela = F_ext(t) at every output [SD eq. (9), "
          "dF_ext/dt term]")
{
    const double F0 = 1e-3, T = 2e4; // T comparable to the approach time from h0 = 10 R
    Loading ramp{[=](double t) { return F0 * (1 + t / T); }, [=](double) { return F0 / T; }};
    const ApproachProblem problem{material, paper_contact_laws(material), ramp, 10.0, 1e-4};
    IntegratorSettings settings;
    settings.tolerance = 1e-10;
    const ApproachRun run = integrate_approach(problem, settings);
    REQUIRE(run.samples.back().t > 0.5 * T); // the load has grown by more than half
    for (const ApproachSample& s : run.samples) {
        CAPTURE(s.t);
        // Without the dF/dt term of eq. (9) the residual would be F(t)/F(0) - 1, i.e. up to O(1). With it:
        // the solver tolerance times the step count, as above (here ~1e-10 x 1e3).
        CHECK_CLOSE(s.rates.F_ela, s.F_ext, (Tolerance{1e-6, 0.0}));
    }
}

TEST_CASE("h(t) equals the quadrature t(h) = int zeta/F dh of eq. (7), error falling with the tolerance [SD "
          "eq. (7)]")
{
    const double kappa = 1e-4;
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-6};
    double previous = INFINITY;
    for (double tolerance : {1e-5, 1e-7, 1e-9}) {
        CAPTURE(tolerance);
        IntegratorSettings settings;
        settings.tolerance = tolerance;
        const ApproachRun run = integrate_approach(problem, settings);
        const ApproachAnalysis a = analyse_approach(problem, run.samples, 0.1);
        double error = 0;
        for (double e : a.h_error)
            error = std::max(error, e);
        CAPTURE(error);
        // Global error <= local tolerance x steps (rk8pd: a few hundred steps).
        CHECK(error <= tolerance * static_cast<double>(run.steps));
        CHECK(error < previous);
        previous = error;
    }
}

TEST_CASE("fixed-step rk4 converges with order 4 in dt on h(t) [GSL rk4, classical Runge-Kutta]")
{
    const double kappa = 1e-2;
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-2};
    std::vector<double> log_dt, log_error;
    for (double dt_over : {8.0, 4.0, 2.0, 1.0}) { // in R/V = 1/kappa; dt |dh-dot/dh|max = 0.44 ... 0.055
        IntegratorSettings settings;
        settings.stepper = "rk4";
        settings.fixed_step = true;
        settings.dt = dt_over / kappa;
        const ApproachRun run = integrate_approach(problem, settings);
        const ApproachAnalysis a = analyse_approach(problem, run.samples, 0.1);
        double error = 0;
        for (double e : a.h_error)
            error = std::max(error, e);
        log_dt.push_back(std::log(dt_over));
        log_error.push_back(std::log(error));
    }
    double c0, c1, cov00, cov01, cov11, chisq;
    gsl_fit_linear(log_dt.data(), 1, log_error.data(), 1, log_dt.size(), &c0, &c1, &cov00, &cov01, &cov11,
                   &chisq);
    INFO("fitted order " << c1);
    // The global error of classical RK4 is O(dt^4) (observed errors 5e-6 ... 1e-9). Below dt = 1 R/V the
    // error meets the round-off floor of delta = (2R + h - X)/2 accumulated over 1e4 steps (~1e-10), hence
    // these dt. The band 4 +- 0.3 allows for the pre-asymptotic largest step (dt |dh-dot/dh| = 0.44).
    CHECK(std::abs(c1 - 4.0) < 0.3);
}

TEST_CASE("a fixed explicit step above ~1/max|dh-dot/dh| stops with a diagnosis; adaptive steps never do "
          "[stability]")
{
    const double kappa = 1e-6;
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-4};
    // max |d h-dot/dh| = lambda2/tau is reached near the Stokes-Poiseuille crossover, ~1/(6 pi) V/R (1.04/(6
    // pi) here).
    double rate_max = 0;
    for (double h = 100; h > 1e-4; h /= 1.2)
        rate_max = std::max(rate_max, std::abs(gap_rate_derivative(problem, h, 0)));
    CHECK_CLOSE(rate_max * 6 * std::acos(-1.0) / kappa, 1.04, (Tolerance{0.02, 0.0}));
    for (const char* stepper : {"rk2", "rk4", "rkf45"}) {
        CAPTURE(stepper);
        IntegratorSettings settings;
        settings.stepper = stepper;
        settings.fixed_step = true;
        settings.dt = 3.0 / rate_max;
        try {
            integrate_approach(problem, settings);
            FAIL("no NumericalError with dt |dh-dot/dh|max = 3");
        } catch (const softgrain::NumericalError& e) {
            CHECK(std::string(e.what()).find("dt |d h-dot/dh|") != std::string::npos);
        }
        settings.dt = 0.2 / rate_max; // well inside the stability and positivity bounds
        CHECK_NOTHROW(integrate_approach(problem, settings));
    }
}
