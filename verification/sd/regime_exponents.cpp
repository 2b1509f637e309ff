// SD Fig. 3a, d, f: the local exponents lambda1 (delta ~ h^lambda1) and lambda2 (h-dot ~ h^lambda2) of
// simulated approaches, in each regime the run crosses, against the scaling theory.
#include "sd/approach.hpp"
#include "sd/approach_analysis.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain::sd;
using softgrain::verification::Tolerance;

namespace {

const Material material; // R = E = eta = 1, alpha = 4/9: kappa = F

struct Simulated
{
    ApproachRun run;
    ApproachAnalysis analysis;
};

Simulated simulate(double kappa)
{
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-7};
    IntegratorSettings settings; // defaults: rk8pd, tolerance 1e-10, 20 samples per decade
    ApproachRun run = integrate_approach(problem, settings);
    ApproachAnalysis analysis = analyse_approach(problem, run.samples, 0.1);
    return {std::move(run), std::move(analysis)};
}

// The width w of a regime bounds the first-order deviation of lambda2 (w/2 for lambda1); the neglected terms
// are quadratic in the small ratios, hence w + w^2. Added: the 3-point difference error of the exponents on
// the 20-per-decade grid, bounded by lambda_error_max (checked below to be < 2e-3).
void check_regime(const RegimePoint& point, double lambda1, double lambda2)
{
    CAPTURE(point.h);
    CAPTURE(point.width);
    const double w = point.width + point.width * point.width + 2e-3;
    CHECK_CLOSE(point.lambda2, lambda2, (Tolerance{0.0, w}));
    CHECK_CLOSE(point.lambda1, lambda1, (Tolerance{0.0, w / 2}));
}

} // namespace

TEST_CASE("measured exponents equal the exact d ln delta/d ln h, d ln|h-dot|/d ln h along the run [SD eqs. "
          "(1)-(7)]")
{
    for (double kappa : {1e-6, 1e-4, 1e-2, 0.3}) {
        CAPTURE(kappa);
        const Simulated s = simulate(kappa);
        // 3-point differences on a grid of 20 samples per decade (spacing 0.115 in ln h): error ~ spacing^2/6
        // times the third derivative of ln delta, ln|h-dot| in ln h, which is O(1) at the crossovers: a few
        // 1e-3 at most.
        CHECK(s.analysis.lambda_error_max < 2e-3);
    }
}

TEST_CASE("kappa = 1e-6 crosses Stokes, Poiseuille and Hertz: lambda2 = 0, 1, 3 and lambda1 = 0, -1/2, 0 [SD "
          "Fig. 3a]")
{
    const Simulated s = simulate(1e-6);
    REQUIRE(s.analysis.stokes);
    REQUIRE(s.analysis.poiseuille);
    REQUIRE(s.analysis.hertz);
    check_regime(*s.analysis.stokes, 0.0, 0.0);
    check_regime(*s.analysis.poiseuille, -0.5, 1.0);
    check_regime(*s.analysis.hertz, 0.0, 3.0);
}

TEST_CASE("large kappa goes from Stokes to Hertz directly: no Poiseuille regime for kappa >= 1e-2 [SD text "
          "on Fig. 3f]")
{
    for (double kappa : {1e-2, 0.3}) {
        CAPTURE(kappa);
        const Simulated s = simulate(kappa);
        REQUIRE(s.analysis.stokes);
        REQUIRE(s.analysis.hertz);
        CHECK_FALSE(s.analysis.poiseuille.has_value());
        check_regime(*s.analysis.stokes, 0.0, 0.0);
        check_regime(*s.analysis.hertz, 0.0, 3.0);
    }
}

TEST_CASE("deflection prefactors: delta/R = 1.591 kappa (Stokes), 1.363 kappa^(2/3) (Hertz) [SD Fig. 3a, "
          "alpha = 4/9]")
{
    const double kappa = 1e-4;
    const Simulated s = simulate(kappa);
    const double alpha = material.alpha;
    // At h0 = 100 R: a = R sqrt2 (1 - R/(2 h0)) to first order, so delta is high by R/(2 h0) = 5e-3.
    CHECK_CLOSE(s.run.samples.front().rates.delta, kappa / (alpha * std::sqrt(2.0)), (Tolerance{6e-3, 0.0}));
    // At h_min = 1e-7 R: delta = 5.9e-3 R, correction h/(3 delta) ~ 6e-6, plus the force-balance drift (<
    // 1e-6).
    CHECK_CLOSE(s.run.samples.back().rates.delta, std::cbrt(kappa * kappa / (2 * alpha * alpha)),
                (Tolerance{2e-5, 0.0}));
    // Stokes gap rate h-dot -> -V/(6 pi) (1 + R/h): 1% high at h0.
    CHECK_CLOSE(s.run.samples.front().rates.h_dot / kappa, -1.0 / (6 * std::acos(-1.0)),
                (Tolerance{1.1e-2, 0.0}));
}
