// compare.ring: a thin elastic ring between two plates by SPD (eta = 0) and by the DPM shell (k_a = 0), both
// from the same E, h, against the inextensible elastica (lib/spd/elastica.hpp). Decisions compare-ring-*.
#include "compare/ring.hpp"
#include "core/fits.hpp"
#include "spd/elastica.hpp"
#include "support/run_softgrain.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <vector>

using namespace softgrain::compare;
using softgrain::verification::Tolerance;

namespace {

constexpr double tau = 1e-5; // relax_tolerance: every unbalanced force component below tau B/R^2

RingComparison squeeze(RingMethod method, int nodes, double strain_max, double strain_step)
{
    RingComparisonSetup setup;
    setup.method = method;
    setup.nodes = nodes;
    // h/R = 0.01: a stretching error of about 2e-5 in F (decision compare-ring-thickness), below the
    // discretisation error at every N used here (>= 6e-4 at eps = 0.3).
    setup.h = 0.01;
    setup.strain_max = strain_max;
    setup.strain_step = strain_step;
    setup.relax_tolerance = tau;
    return compress_ring(setup, [](double) {});
}

// The recorded state at eps (a multiple of the strain step).
const RingObservation& at_strain(const RingComparison& r, double eps)
{
    for (const RingObservation& o : r.states)
        if (std::abs(o.strain - eps) < 1e-9) return o;
    FAIL("no state at eps = " << eps);
    return r.states.front();
}

} // namespace

TEST_CASE("both methods converge to the elastica at eps = 0.3 at second order [elastica, compare.ring]")
{
    const std::vector<int> resolutions = {16, 32, 64, 128};
    std::vector<double> nodes, spd_errors, dpm_errors;
    for (int n : resolutions) {
        const RingObservation spd = at_strain(squeeze(RingMethod::spd, n, 0.3, 0.1), 0.3);
        const RingObservation dpm = at_strain(squeeze(RingMethod::dpm, n, 0.3, 0.1), 0.3);
        CAPTURE(n);
        // One discrete model relaxed by two solvers (decision compare-ring-mapping): each relaxed state
        // balances its plate forces up to the sum of its 2N unbalanced components, at most 2N tau B/R^2, so
        // the two forces differ by at most 4 N tau in F R^2/B.
        CHECK_CLOSE(spd.force, dpm.force, (Tolerance{0, 4 * n * tau}));
        nodes.push_back(n);
        spd_errors.push_back(elastica_errors(spd).force);
        dpm_errors.push_back(elastica_errors(dpm).force);
    }
    // Order 2 (central differences, decision compare-ring-convergence-order). The lift-off point falls
    // between vertices, so single errors scatter by up to a factor 3 about C N^-2; over ln(128/16) = 2.08
    // that moves a least-squares slope by up to ln 3/2.08 = 0.53. A first-order error (e.g. a hinge
    // stiffness off by O(l0)) gives slopes near 1 and fails.
    const double spd_order = -*softgrain::fit_power_law_exponent(nodes, spd_errors);
    const double dpm_order = -*softgrain::fit_power_law_exponent(nodes, dpm_errors);
    CHECK_CLOSE(spd_order, 2.0, (Tolerance{0, 0.55}));
    CHECK_CLOSE(dpm_order, 2.0, (Tolerance{0, 0.55}));
    // And the finest error lies within that scatter of the second-order line through the coarsest one.
    const double predicted = spd_errors.front() * std::pow(nodes.front() / nodes.back(), 2);
    CHECK(spd_errors.back() <= 3 * predicted);
    CHECK(dpm_errors.back() <= 3 * predicted);
}

TEST_CASE("same bending rigidity: small-strain stiffness F R^2/(B eps) equals the elastica's [compare.ring]")
{
    // At eps = 0.01 the ring is in its linear regime (point contact); the elastica's F R^2/B over eps is
    // close to 2/(pi/4 - 2/pi) = 13.44 of linear ring theory. A method whose B differed from k_b l0 would
    // be off by that factor.
    const int n = 64;
    const double eps = 0.01, l0 = 2 * std::sin(std::numbers::pi / n); // over R
    const double elastica = softgrain::spd::elastica_ring_between_plates(eps).force;
    for (RingMethod method : {RingMethod::spd, RingMethod::dpm}) {
        const RingObservation o = at_strain(squeeze(method, n, eps, eps), eps);
        CAPTURE(static_cast<int>(method));
        // Second-order discretisation: relative error O((l0/R)^2) = 9.6e-3 at N = 64.
        CHECK_CLOSE(o.force / eps, elastica / eps, (Tolerance{l0 * l0, 0}));
    }
}

TEST_CASE("compare.ring's largest errors are taken over eps = 0.1, 0.2, ... only")
{
    // Observations at eps = 0.05, 0.1, 0.15, 0.2 whose forces are off the elastica by 50%, 2%, 40%, 30%: the
    // maximum over the reported strains is 30%; the larger errors at eps = 0.05 and 0.15 are not reported.
    const double strains[] = {0.05, 0.1, 0.15, 0.2}, force_errors[] = {0.5, 0.02, 0.4, 0.3};
    RingComparison comparison;
    comparison.states.push_back({}); // eps = 0
    for (int k = 0; k < 4; ++k) {
        const softgrain::spd::ElasticaState elastica =
            softgrain::spd::elastica_ring_between_plates(strains[k]);
        comparison.states.push_back({strains[k], elastica.force * (1 + force_errors[k]), elastica.width,
                                     elastica.volume, elastica.contact_length});
    }
    const std::optional<RingErrors> worst = largest_elastica_errors(comparison);
    REQUIRE(worst.has_value());
    CHECK_CLOSE(worst->force, 0.3, (Tolerance{1e-12, 0})); // round-off of F (1 + e)/F - 1
    CHECK(worst->width == 0.0);
    CHECK(reported_strain(0.1 + 0.2) == true); // 0.30000000000000004: a tenth up to round-off
    CHECK(reported_strain(0.0) == false);
    // Below eps = 0.1 nothing is reported.
    comparison.states.resize(2);
    CHECK(!largest_elastica_errors(comparison).has_value());
}

TEST_CASE("compare.ring: refused inputs (exit 2) and a time step above the stability limit (exit 3)")
{
    using softgrain::verification::run_softgrain;
    const auto dir = std::filesystem::temp_directory_path() / "softgrain-compare-ring-cli";
    const std::string out = " --quiet --out " + dir.string();
    const auto odd = run_softgrain("run compare.ring --set nodes=30" + out);
    CHECK(odd.exit_code == 2);
    CHECK(odd.output.find("multiple of 4") != std::string::npos);
    const auto step = run_softgrain("run compare.ring --set strain_step=0.03" + out);
    CHECK(step.exit_code == 2);
    CHECK(step.output.find("strain_step") != std::string::npos);
    const auto fast = run_softgrain("run compare.ring --set nodes=16 --set dt_factor=0.9" + out);
    CHECK(fast.exit_code == 3);
    CHECK(fast.output.find("stability limit") != std::string::npos);
    CHECK(!std::filesystem::exists(dir / "compare.ring"));
}
