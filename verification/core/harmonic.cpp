// core.harmonic: velocity Verlet on a linear spring against its exact discrete theory.
#include "core/harmonic.hpp"
#include "core/errors.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <gsl/gsl_fit.h>
#include <numbers>
#include <string>
#include <vector>

using namespace softgrain;
using softgrain::verification::Tolerance;

namespace {
const HarmonicOscillator oscillator{2.0, 50.0}; // omega = 5 rad/s, T = 1.2566 s, dt_c = 0.4 s
}

TEST_CASE("velocity Verlet period error is second order in dt [theory: T~ = T (1 + (omega dt)^2/24)]")
{
    // Period error |T~ - T| over dt = dt_c/40 ... dt_c/320; the slope of log error against log dt is the
    // order.
    std::vector<double> log_dt, log_error;
    for (double dt = 0.01; dt >= 0.00125; dt /= 2) {
        const HarmonicRun run = simulate_harmonic(oscillator, dt, 40.0);
        log_dt.push_back(std::log(dt));
        log_error.push_back(std::log(std::abs(run.period - oscillator.period())));
    }
    double intercept, slope, cov00, cov01, cov11, sum_squares;
    gsl_fit_linear(log_dt.data(), 1, log_error.data(), 1, log_dt.size(), &intercept, &slope, &cov00, &cov01,
                   &cov11, &sum_squares);
    INFO("fitted order " << slope);
    // The acceptance band: 2 +- 0.1. The leading term (omega dt)^2/24 dominates the O(dt^4) term by
    // a factor > 1e3 at these dt, so the fitted slope is 2 to much better than 0.1.
    CHECK(std::abs(slope - 2.0) < 0.1);
}

TEST_CASE("measured period equals the exact discrete period 2 pi / omega~ [sin(omega~ dt/2) = omega dt/2]")
{
    for (double ratio : {0.01, 0.1, 0.5, 0.9}) {
        const double dt = ratio * oscillator.critical_time_step();
        const HarmonicRun run = simulate_harmonic(oscillator, dt, 50.0);
        CAPTURE(ratio);
        // The zero crossings are interpolated linearly; at x = 0 the curvature of the cosine vanishes, so the
        // interpolation error is O((omega~ dt)^3) per crossing and averages over 50 periods: 1e-4 relative
        // bounds it even at dt/dt_c = 0.9 (observed: ~1e-5 there, round-off at small dt).
        CHECK_CLOSE(run.period, verlet_period(oscillator, dt), (Tolerance{1e-4, 0.0}));
    }
}

TEST_CASE("energy error of velocity Verlet is bounded by (dt/dt_c)^2 and reaches it [shadow energy]")
{
    for (double ratio : {0.05, 0.3, 0.7}) {
        const double dt = ratio * oscillator.critical_time_step();
        const HarmonicRun run = simulate_harmonic(oscillator, dt, 100.0);
        const double bound = verlet_energy_error_bound(oscillator, dt);
        CAPTURE(ratio);
        // Never above the bound (up to round-off of E over many steps) ...
        CHECK(run.energy_error_max <= bound * (1.0 + 1e-9));
        // ... and reached where x passes through 0: E/E0 - 1 = -q (1 - x^2/A^2), and over 100 periods a step
        // lands within 0.05 rad of a zero of x, so the sampled maximum is within 0.3% of q.
        CHECK_CLOSE(run.energy_error_max, bound, (Tolerance{3e-3, 0.0}));
    }
}

TEST_CASE("a time step above the stability limit dt_c = 2/omega stops with a diagnosis naming the limit")
{
    for (double ratio : {1.001, 1.2, 3.0}) {
        const double dt = ratio * oscillator.critical_time_step();
        CAPTURE(ratio);
        try {
            simulate_harmonic(oscillator, dt, 50.0);
            FAIL("no NumericalError above the stability limit");
        } catch (const NumericalError& e) {
            CHECK(std::string(e.what()).find("stability limit") != std::string::npos);
            CHECK(e.step > 0);
        }
    }
    // Just below the limit the run is stable, however long: the energy never exceeds E0.
    CHECK_NOTHROW(simulate_harmonic(oscillator, 0.999 * oscillator.critical_time_step(), 200.0));
}
