// Shear modulus by Lees-Edwards strain steps (DPM sec. 9.4.3) against the analytic modulus of a compressed
// triangular crystal of disks with linear springs (eq. 9.4): every particle is a centre of inversion, so the
// response is affine and, per particle (area A_0 = sqrt(3)/2 a^2, three bonds at 0, 60, 120 degrees),
//   d^2U/dgamma^2 = sum_b [k (x y/r)^2 - f (y^2/r - x^2 y^2/r^3)] = (3/8) k a^2 - (9/8) f a,
// with f = k (sigma - a) the compressive bond force; P = 3 f a/(2 A_0) = sqrt(3) f/a. Hence
//   G = (1/A_0) d^2U/dgamma^2 = sqrt(3)/4 k - (3/4) P.
#include "dpm/protocols/shear_modulus.hpp"
#include "core/errors.hpp"
#include "dpm/analysis/linear_shear_modulus.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/shear_modulus_ensemble.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

TEST_CASE(
    "G from Lees-Edwards steps of 5e-9 = sqrt(3)/4 k_c - 3/4 P for a compressed triangular disk crystal "
    "[DPM sec. 9.4.3, eq. (9.4)]")
{
    for (double a : {0.999, 0.98}) {
        DpmSystem s;
        s.interaction = InteractionKind::rough;
        s.kc = 1.0;
        const int nx = 8, ny = 8;
        s.box = Eigen::Vector2d(nx * a, ny * a * std::sqrt(3.0) / 2);
        Eigen::VectorXd x;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                Eigen::Matrix2Xd c(2, 1);
                c << (i + 0.5 * (j % 2)) * a, j * a * std::sqrt(3.0) / 2;
                s.add_particle(c, 1.0, ShapeParameters{}, x);
            }
        const double p = pressure(stress_tensor(s, x));
        const ShearModulusResult g = shear_modulus(s, x, 5e-9, 2, 1e-13);
        CAPTURE(a);
        // Analytic pressure of the crystal first (checks the setup).
        CHECK_CLOSE(p, std::sqrt(3.0) * (1 - a) / a, (Tolerance{1e-12, 0}));
        // Stress change per step G dgamma ~ 2e-9 against stress round-off ~1e-16 x 1e-2 and the O(dgamma)
        // nonlinearity of the stress (relative 5e-9): 1e-5 relative covers both with margin.
        CHECK_CLOSE(g.modulus, std::sqrt(3.0) / 4 - 0.75 * p, (Tolerance{1e-5, 0}));
    }
}

// Near onset Newton's damped steps can crawl (shear_modulus.hpp). A floppy packing jammed as DPM-Fig9.16a's
// first one with fire_step = 1, but to the onset alone (16 particles of 10/14 vertices at P = 1e-6 k_a a0,
// seed 1), is such a case: Newton alone stops short of the tolerance after its 30 steps. Given the jamming
// protocol's FIRE settings, the procedure relaxes it with FIRE first and polishes to round-off; its
// finite-strain G then equals the linear response at the same equilibrium (linear_shear_modulus.hpp).
// Bound: the residual force (largest component F below 1e-14 k_a a0 = 1.8e-15 after the polish) enters the
// stress through its virial, at most sqrt(n) L F / A = 2.2e-15 (n = 384 coordinates, box side L = 15.8,
// area A = 248), against the stress change G dgamma = 2.2e-13 of a step: 1e-2 relative. The nonlinearity
// of a step (displacements L dgamma = 8e-8 against distances ~ 1) is far below. (On DPM-Fig9.16a's packing,
// FIRE to a tenth of the tolerance without the polish gave a G a quarter of the linear response's.)
TEST_CASE("where Newton crawls, FIRE relaxes first and G equals the linear response [DPM sec. 9.4.3]")
{
    JamOptions o;
    o.model = JamModel::floppy;
    o.particles = 16;
    o.nodes_small = 10;
    o.nodes_large = 14;
    o.pressure_onset = o.pressure_max = 1e-6;
    o.pressures = 0;
    o.seed = 1;
    o.fire_step = 1;
    const JamResult r = jam(o);
    const double tolerance = 1e-10 * r.pressure_unit; // dpm.shear_modulus's force_tolerance
    CHECK_THROWS_AS(shear_modulus(r.system, r.x, 5e-9, 2, tolerance), NumericalError); // Newton alone
    const ShearModulusResult g = shear_modulus(r.system, r.x, 5e-9, 2, tolerance, {}, r.fire);
    CHECK(g.force_max < tolerance);
    const LinearShearModulus linear = linear_shear_modulus(r.system, g.equilibrium);
    MESSAGE("G " << g.modulus << ", linear response " << linear.modulus << ", box "
                 << r.system.box->transpose() << ", largest force after the polish " << g.force_max);
    CHECK(linear.negative_modes == 0);
    CHECK_CLOSE(g.modulus, linear.modulus, (Tolerance{1e-2, 0}));
}

TEST_CASE("the ensemble's exponent eta of <G> ~ P^eta: its jackknife standard error over the packings")
{
    using softgrain::verification::round_off;
    // Members with the same pressures (onset 0.5, then 1 and e, so that ln P = 0, 1 above onset).
    const auto member = [](std::vector<double> modulus) {
        ModulusMember m;
        m.pressure = {0.5, 1.0, std::exp(1.0)};
        m.modulus = std::move(modulus);
        return m;
    };
    // G_k = c_k P^(1/2) for every packing: every leave-one-out mean has the exponent 1/2, so the standard
    // error is zero (round-off of the logarithms of O(1) means).
    std::vector<ModulusMember> same;
    for (double c : {1.0, 2.0, 3.0})
        same.push_back(member({c * std::sqrt(0.5), c, c * std::exp(0.5)}));
    const auto zero = jackknife_exponent_error(same);
    REQUIRE(zero);
    CHECK_CLOSE(*zero, 0.0, (Tolerance{0, 16 * round_off}));
    // G = 1 at P = 1 and a_k at P = e: eta_(k) = ln(mean of the other a), here ln 3, ln 2.5 and ln 1.5 for
    // a = (1, 2, 4); SE^2 = (n - 1)/n sum_k (eta_(k) - mean)^2, Tukey's estimator, written out.
    const std::vector<ModulusMember> spread = {member({1, 1, 1}), member({1, 1, 2}), member({1, 1, 4})};
    const double e1 = std::log(3.0), e2 = std::log(2.5), e3 = std::log(1.5), mean = (e1 + e2 + e3) / 3;
    const double expected = std::sqrt(
        2.0 / 3.0 * ((e1 - mean) * (e1 - mean) + (e2 - mean) * (e2 - mean) + (e3 - mean) * (e3 - mean)));
    const auto se = jackknife_exponent_error(spread);
    REQUIRE(se);
    CHECK_CLOSE(*se, expected, (Tolerance{16 * round_off, 0}));
    // Without the third packing <G> at P = e is (-1 + 1)/2 = 0: one pressure with <G> > 0, no exponent, so
    // no standard error; nor with one packing.
    CHECK_FALSE(jackknife_exponent_error({member({1, 1, -1}), member({1, 1, 1}), member({1, 1, 3})}));
    CHECK_FALSE(jackknife_exponent_error({member({1, 1, 2})}));
}
