// SD Fig. 3b: the Poiseuille-Hertz crossover kappa ~ (h/R)^(3/2), and the Poiseuille window that shrinks and
// vanishes as kappa grows; and both as sd.phase_diagram reduces them (sd/phase_diagram.hpp).
#include "core/fits.hpp"
#include "sd/approach.hpp"
#include "sd/approach_analysis.hpp"
#include "sd/phase_diagram.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <optional>
#include <vector>

using namespace softgrain::sd;
using softgrain::fit_power_law;
using softgrain::Line;
using softgrain::verification::Tolerance;

namespace {
const Material material; // R = E = eta = 1: kappa = F

std::vector<ApproachSample> approach(double kappa)
{
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-8};
    return integrate_approach(problem, IntegratorSettings{}).samples;
}

ApproachAnalysis analyse(double kappa, const std::vector<ApproachSample>& samples)
{
    const ApproachProblem problem{material, paper_contact_laws(material), constant_loading(kappa), 100.0,
                                  1e-8};
    return analyse_approach(problem, samples, 0.1);
}
} // namespace

TEST_CASE(
    "simulated delta = h crossover: kappa = 2 alpha (h/R)^(3/2), slope 3/2 [SD text: kappa ~ (h/R)^(3/2)]")
{
    // Derivation: at delta = h, eq. (1) with eqs. (3), (5) gives kappa = alpha sqrt2 (h/R) sqrt(h-bar/R +
    // h/R), which tends to 2 alpha (h/R)^(3/2) = (8/9)(h/R)^(3/2) for h << R: the order-one factor of the
    // paper's "~" is 2 alpha.
    std::vector<double> h_crossover, kappas;
    for (double kappa : {1e-7, 1e-6, 1e-5, 1e-4}) {
        CAPTURE(kappa);
        const ApproachAnalysis a = analyse(kappa, approach(kappa));
        REQUIRE(a.h_crossover.has_value());
        // The crossover is interpolated linearly in ln(delta/h) between samples 0.115 apart in ln h: the
        // error in h is ~ spacing^2/8 times the curvature of ln(delta/h), below 1e-3 relative (3/2 of it in
        // kappa).
        CHECK_CLOSE(crossover_kappa_paper(material, *a.h_crossover), kappa, (Tolerance{1.5e-3, 0.0}));
        h_crossover.push_back(*a.h_crossover);
        kappas.push_back(kappa);
    }
    const std::optional<Line> power_law = fit_power_law(h_crossover, kappas);
    REQUIRE(power_law.has_value());
    // h_crossover <= 3e-3 R here: h-bar = h (1 - h/R) bends the slope by ~h/(2R) < 2e-3; interpolation adds
    // 1e-3.
    CHECK_CLOSE(power_law->slope, 1.5, (Tolerance{0.0, 5e-3}));
    CHECK_CLOSE(std::exp(power_law->intercept), 2 * material.alpha, (Tolerance{2e-2, 0.0}));
}

TEST_CASE("the Poiseuille window (|lambda2 - 1| <~ 0.1) shrinks as kappa grows and vanishes by kappa = 1e-3 "
          "[SD text]")
{
    double previous = INFINITY;
    for (double kappa : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.3}) {
        CAPTURE(kappa);
        const auto range = regime_range(approach(kappa), Regime::poiseuille, material.radius, 0.1);
        const double decades = range ? range->decades() : 0.0;
        CAPTURE(decades);
        CHECK(decades <= previous);
        if (kappa >= 1e-3) CHECK(decades == 0.0);
        // Theory: w_P = h/R + 3 delta/h <= 0.1 with delta = kappa/(alpha sqrt2) (h/R)^(-1/2) has solutions
        // only for kappa below 1.2e-4 (w_P has its minimum (5/3)(h/R) at h/R = (7.16 kappa)^(2/5)).
        if (kappa <= 1e-5) CHECK(decades > 0.5);
        previous = decades;
    }
}

TEST_CASE(
    "phase diagram over the paper's kappa range: crossovers on the delta = h line, slope 3/2, Poiseuille "
    "window nonincreasing and gone above kappa = 1.2e-4 [SD Fig. 3b]")
{
    PhaseDiagramSetup setup; // the paper's range: 12 kappas from 1e-6 to 0.3
    setup.pair = {material, paper_contact_laws(material), constant_loading(1e-6), 100.0, 1e-7};
    int reports = 0;
    const PhaseDiagram diagram = phase_diagram(setup, [&reports](double) { ++reports; });
    CHECK(reports == 12);
    REQUIRE(diagram.points.size() == 12);
    CHECK(diagram.points.front().kappa == 1e-6);
    CHECK_CLOSE(diagram.points.back().kappa, 0.3, (Tolerance{4 * softgrain::verification::round_off, 0.0}));
    // As the first test: 1.5e-3 from the interpolation of the crossover; the slope over h_crossover <= 1e-2 R,
    // where h-bar = h (1 - h/R) bends it by at most h/(2R) = 5e-3, plus 1e-3 of interpolation.
    CHECK(diagram.crossover_relative_error_max <= 1.5e-3);
    REQUIRE(diagram.crossover_line.has_value());
    CHECK(diagram.crossover_points >= 4);
    CHECK_CLOSE(diagram.crossover_line->slope, 1.5, (Tolerance{0.0, 6e-3}));
    // The Poiseuille window, as the second test: never widening, gone above kappa = 1.2e-4 (theory).
    CHECK(diagram.poiseuille_window_nonincreasing);
    CHECK(diagram.points.front().poiseuille_decades() > 0.5);
    REQUIRE(diagram.kappa_poiseuille_last.has_value());
    REQUIRE(diagram.kappa_poiseuille_vanishes.has_value());
    CHECK(*diagram.kappa_poiseuille_last < 1.2e-4);
    CHECK(*diagram.kappa_poiseuille_vanishes > *diagram.kappa_poiseuille_last);
}
