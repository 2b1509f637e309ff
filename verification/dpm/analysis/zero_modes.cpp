// DPM section 9.4.3, Fig. 9.14(a): zero modes of the dynamical matrix (eq. 9.28) of single particles.
// Floppy (A0 > A_min): N_dof - N_c = 2N - (N + 1) = N - 1; elastic shell and surface-tension particle: 3
// (two translations, one rotation). Threshold lambda~ < 1e-13 (the paper's).
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/single_particle.hpp"
#include "support/tolerance.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

int zero_modes(ShapeModel model, int n, double A0, const ShapeStiffness& k, std::uint64_t seed = 1)
{
    const SingleParticle p = single_particle_equilibrium(model, n, 1.0, A0, k, seed);
    const Eigen::VectorXd lambda = vibrational_modes(p.system, p.x).eigenvalues / (k.ka * 1.0);
    // The count must not depend on where exactly the threshold sits: the gap between the largest zero
    // mode and the smallest non-zero mode spans many decades (round-off ~1e-15 vs O(1e-2)).
    const int zero = count_zero_modes(lambda, 1e-13);
    if (zero < lambda.size()) CHECK(lambda(zero) > 1e-6);
    return zero;
}

} // namespace

TEST_CASE("floppy particle: exactly N - 1 zero modes [DPM sec. 9.4.3, Fig. 9.14a]")
{
    const ShapeStiffness k;
    for (int n : {6, 10, 14, 20}) {
        CAPTURE(n);
        CHECK(zero_modes(ShapeModel::floppy, n,
                         1.04 * minimum_shape_parameter(n) / minimum_shape_parameter(10), k) == n - 1);
    }
    // Fig. 9.14(a) itself: N = 10, A0 = 1.04 -> 9; also for other seeds (other points of the floppy
    // manifold).
    for (std::uint64_t seed : {1u, 2u, 3u})
        CHECK(zero_modes(ShapeModel::floppy, 10, 1.04, k, seed) == 9);
}

TEST_CASE("elastic shell and surface-tension particle: exactly 3 zero modes [DPM sec. 9.4.3, Fig. 9.14a]")
{
    for (int n : {6, 10, 14, 20}) {
        CAPTURE(n);
        const double a_min = minimum_shape_parameter(n);
        CHECK(zero_modes(ShapeModel::shell, n, a_min, ShapeStiffness{}) == 3);
        CHECK(zero_modes(ShapeModel::surface_tension, n, a_min, ShapeStiffness{}) == 3);
        // Table 9.1 says k_l ~ 0 for the surface-tension particle, the caption of Fig. 9.14(a) k_l > 0:
        // both readings give 3 (decision dpm-surface-tension-kl).
        ShapeStiffness with_kl;
        with_kl.kl_surface = 1.0;
        CHECK(zero_modes(ShapeModel::surface_tension, n, a_min, with_kl) == 3);
    }
}

TEST_CASE("surface-tension particle relaxes to the regular polygon, A = A_min [DPM Table 9.1]")
{
    for (int n : {6, 10}) {
        const SingleParticle p = single_particle_equilibrium(ShapeModel::surface_tension, n, 1.0,
                                                             minimum_shape_parameter(n), {}, 1);
        // Newton-polished to forces of 1e-14: the shape parameter is A_min to round-off.
        CHECK_CLOSE(shape_parameter(particle_perimeter(p.x, 0, n), particle_area(p.x, 0, n)),
                    minimum_shape_parameter(n), (Tolerance{1e-12, 0}));
    }
}

TEST_CASE("Delta U along a mode: ~ lambda dr^2/2 for quadratic modes, ~ dr^4 along floppy zero modes [DPM "
          "Fig. 9.14c]")
{
    const SingleParticle p = single_particle_equilibrium(ShapeModel::floppy, 10, 1.0, 1.04, {}, 1);
    const ModeSpectrum modes = vibrational_modes(p.system, p.x);
    const int zero = count_zero_modes(modes.eigenvalues, 1e-13);
    const double smallest = modes.eigenvalues(zero), dr = 1e-3;
    for (Eigen::Index m = 0; m < modes.eigenvalues.size(); ++m) {
        const Eigen::VectorXd e = modes.eigenvectors.col(m);
        const double lambda = modes.eigenvalues(m);
        // The even part (dU(+dr) + dU(-dr))/2 = lambda dr^2/2 + O(dr^4): cubic terms cancel.
        const double du =
            0.5 * (energy_change_along(p.system, p.x, e, dr) + energy_change_along(p.system, p.x, e, -dr));
        CAPTURE(m);
        if (m >= zero) {
            // relative correction O(dr^2 |U''''| / lambda) <~ 1e-6 / 1e-2 for the smallest lambda ~ 1e-2.
            CHECK_CLOSE(du, 0.5 * lambda * dr * dr, (Tolerance{1e-3, 0}));
        } else {
            // A zero mode has no dr^2 term: far below the softest quadratic mode, and quartic (translations:
            // no change at all).
            CHECK(du < 1e-2 * 0.5 * smallest * dr * dr);
            const double du2 = 0.5 * (energy_change_along(p.system, p.x, e, 2 * dr) +
                                      energy_change_along(p.system, p.x, e, -2 * dr));
            if (du > 1e-18) CHECK_CLOSE(std::log2(du2 / du), 4.0, (Tolerance{0, 0.01})); // O(dr^2) correction
        }
    }
}

TEST_CASE("Newton polish: quadratic inside the basin, damped where a full step would raise the force")
{
    // U = sqrt(1 + x^2): convex, minimum at 0, force -x/sqrt(1 + x^2), Newton map x -> -x^3. From x = 0.5 the
    // iterates 0.5, -0.125, 2e-3, -7.5e-9, 4e-25 reach a force below 1e-14 in four full steps. From x = 2
    // the full steps diverge (-8, 512, ...); the damped step (a quarter: x = -0.5) enters the basin.
    const EnergyWithDerivatives energy = [](const Eigen::VectorXd& y, Eigen::VectorXd* g,
                                            Eigen::MatrixXd* h) {
        const double r = std::sqrt(1 + y(0) * y(0));
        if (g) (*g)(0) += y(0) / r;
        if (h) (*h)(0, 0) += 1 / (r * r * r);
        return r;
    };
    for (double start : {0.5, 2.0}) {
        CAPTURE(start);
        Eigen::VectorXd x(1);
        x << start;
        CHECK_CLOSE(polish_newton(energy, x, 1e-14, 30), 0.0, (Tolerance{0, 1e-14}));
        CHECK_CLOSE(x(0), 0.0, (Tolerance{0, 1e-14}));
    }
}
