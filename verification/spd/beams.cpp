// SPD section 3, Figs. 7-8: beams of hinge-connected nodes against point-load beam theory.
#include "spd/beam.hpp"
#include "support/tolerance.hpp"

#include <gsl/gsl_fit.h>

#include <vector>

using namespace softgrain::spd;
using softgrain::verification::Tolerance;

namespace {
BeamSetup setup(BeamSupport support, int nodes)
{
    BeamSetup b;
    b.support = support;
    b.nodes = nodes;
    b.material = {1e7, 0.3, 0.05, 0.01};
    b.length = 1.0;
    // Small load: delta_max/L ~ 1e-3, so the geometric nonlinearity (relative O((delta/L)^2)) is ~1e-6.
    b.force = 1e-3 * beam_flexural_rigidity(b) / (b.length * b.length);
    return b;
}
} // namespace

TEST_CASE("beam deflections equal the exact discrete hinge-chain result [SPD eqs. (15), (17) point load]")
{
    for (auto support : {BeamSupport::cantilever, BeamSupport::simple}) {
        for (int nodes : {9, 21}) {
            const BeamSetup b = setup(support, nodes);
            const BeamResult r = simulate_beam(b);
            CAPTURE(nodes);
            // Exact for rigid segments and hinge springs in the small-load limit; the residuals are the
            // relaxation tolerance (unbalanced force 1e-5 F, i.e. a deflection error of that order times the
            // few nodes that carry it) and the geometric nonlinearity (~(delta/L)^2 = 1e-6): 1e-4 covers
            // both.
            CHECK_CLOSE(r.deflection_max / beam_deflection_max_theory(b), beam_discrete_ratio(support, nodes),
                        (Tolerance{1e-4, 0}));
        }
    }
}

TEST_CASE("beam profiles at 21 nodes follow the point-load shapes [SPD eq. (14); 3 xi - 4 xi^3]")
{
    for (auto support : {BeamSupport::cantilever, BeamSupport::simple}) {
        const BeamSetup b = setup(support, 21);
        const BeamResult r = simulate_beam(b);
        double worst = 0, worst_eq16 = 0;
        for (std::size_t k = 0; k < r.x.size(); ++k) {
            const double xi = r.x[k] / b.length;
            const double shape =
                support == BeamSupport::cantilever ? cantilever_shape(xi) : simple_point_load_shape(xi);
            worst = std::max(worst, std::abs(r.deflection[k] / r.deflection_max - shape));
            if (support == BeamSupport::simple)
                worst_eq16 = std::max(worst_eq16, std::abs(r.deflection[k] / r.deflection_max -
                                                           simple_uniform_load_shape_eq16(xi)));
        }
        INFO("max |delta/delta_max - theory| = " << worst);
        // The discrete shape differs from the continuum one by O(1/n) near the clamp (hinge at node 0: the
        // cantilever's first element rotates rigidly, delta_1/delta_max = 3/(2n) + O(1/n^2) vs 3/(2n^2));
        // with n = 20 the largest difference is bounded by 3/(2n) = 0.075 and observed ~0.05 for the
        // cantilever; the simply supported (second-order) shape by 2/n^2 = 0.005.
        CHECK(worst < (support == BeamSupport::cantilever ? 0.075 : 0.005));
        // The printed eq. (16) (uniform-load shape) is off by up to 0.026 from the point-load result.
        if (support == BeamSupport::simple) CHECK(worst_eq16 > 0.02);
    }
}

TEST_CASE("delta_max/delta_th -> 1 as N grows, nearly linearly in 1/N [SPD Fig. 8]")
{
    for (auto support : {BeamSupport::cantilever, BeamSupport::simple}) {
        std::vector<double> inv_n, ratio, exact;
        for (int nodes : {17, 33, 65}) {
            const BeamSetup b = setup(support, nodes);
            inv_n.push_back(1.0 / nodes);
            ratio.push_back(simulate_beam(b).deflection_max / beam_deflection_max_theory(b));
            exact.push_back(beam_discrete_ratio(support, nodes));
        }
        double c0, c1, e0, e1, cov00, cov01, cov11, ss;
        gsl_fit_linear(inv_n.data(), 1, ratio.data(), 1, inv_n.size(), &c0, &c1, &cov00, &cov01, &cov11, &ss);
        gsl_fit_linear(inv_n.data(), 1, exact.data(), 1, inv_n.size(), &e0, &e1, &cov00, &cov01, &cov11, &ss);
        INFO("extrapolated ratio " << c0 << ", slope " << c1);
        // The issue: extrapolated limit 1 within 1%. A linear fit of a ratio 1 + a/N + b/N^2 leaves an
        // intercept error of order b/N_min^2 ~ 1e-3 here.
        CHECK_CLOSE(c0, 1.0, (Tolerance{0.01, 0}));
        // Over-estimate (ratio above 1), as in the paper.
        for (double value : ratio)
            CHECK(value > 1.0);
        // The fitted slope equals the slope of the same fit through the exact discrete ratios (cantilever
        // ~3/2: first order; simply supported ~0: second order); each ratio carries <= 1e-4 of relaxation
        // error, which moves a slope fitted over 1/N in [1/65, 1/17] by < 1e-4/0.04 = 2.5e-3.
        CHECK_CLOSE(c1, e1, (Tolerance{0, 5e-3}));
    }
}
