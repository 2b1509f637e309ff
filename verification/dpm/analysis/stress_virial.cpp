// DPM eqs. (9.25)-(9.26): the virial stress of a periodic system of deformable particles with many-body
// shape terms equals the strain derivative of the energy, Sigma_aa = -(1/A) dU/d(eps_aa), under a
// homogeneous strain of every vertex and of the box. Holds for any configuration (not only equilibria):
// the test uses random overlapping particles across the periodic boundaries, rough and smooth.
#include "core/rng.hpp"
#include "dpm/analysis/packing_fraction.hpp"
#include "dpm/analysis/stress.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// Dense random periodic system: elastic shells with random shapes, many contacts, several across the box.
DpmSystem random_periodic(InteractionKind kind, Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = kind;
    s.kc = 1.0;
    s.box = Eigen::Vector2d(8.0, 7.0);
    ShapeParameters shape;
    shape.ka = 0.9;
    shape.a0 = 1.2;
    shape.kl = 2.0;
    shape.l0 = 0.8;
    shape.kb = 0.3;
    shape.theta0 = 2 * std::numbers::pi / 6;
    shape.gamma = 0.1;
    for (int m = 0; m < 22; ++m) {
        const Eigen::Vector2d c(rng.uniform(0, 8), rng.uniform(0, 7));
        Eigen::Matrix2Xd v = regular_polygon(6, 0.75, c, rng.uniform(0, 2 * std::numbers::pi));
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.08 * rng.uniform(-1, 1); // seeded (not std::rand: independent of test order)
        s.add_particle(v, rng.uniform(0.6, 0.9), shape, x);
    }
    return s;
}

// U after stretching x (axis 0) or y (axis 1) by 1 + e, vertices and box together.
double strained_energy(DpmSystem s, Eigen::VectorXd x, int axis, double e)
{
    for (Eigen::Index v = 0; v < x.size() / 2; ++v)
        x(2 * v + axis) *= 1 + e;
    (*s.box)(axis) *= 1 + e;
    return total_energy(s, x, nullptr, nullptr);
}

} // namespace

TEST_CASE("virial stress = -(1/A) dU/d(strain) with periodic images and many-body shape terms [DPM eqs. "
          "(9.25)-(9.26)]")
{
    Rng rng(5);
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        for (int sample = 0; sample < 3; ++sample) {
            Eigen::VectorXd x;
            const DpmSystem s = random_periodic(kind, rng, x);
            const Eigen::Matrix2d stress = stress_tensor(s, x);
            const double area = s.box->prod();
            CAPTURE(sample);
            CAPTURE(kind == InteractionKind::rough ? "rough" : "smooth");
            for (int axis : {0, 1}) {
                const double e = 1e-6;
                const double derivative =
                    (strained_energy(s, x, axis, e) - strained_energy(s, x, axis, -e)) / (2 * e);
                // Central difference, e = 1e-6: truncation e^2 |U'''| ~ 1e-12 U, round-off eps U/e ~ 1e-10 U:
                // 1e-7 relative (plus 1e-9 absolute for U ~ 1) is far from both and from any missing term.
                CHECK_CLOSE(-area * stress(axis, axis), derivative, (Tolerance{1e-7, 1e-9}));
            }
            // Non-vacuous: contacts and shape deformation both contribute.
            CHECK(total_energy(s, x, nullptr, nullptr, interaction_part) > 0);
            CHECK(total_energy(s, x, nullptr, nullptr, shape_part) > 0);
        }
    }
}

TEST_CASE("interaction virial does not depend on the periodic image: shifting a particle by a box vector "
          "[DPM eq. (9.24)]")
{
    Rng rng(8);
    Eigen::VectorXd x;
    const DpmSystem s = random_periodic(InteractionKind::rough, rng, x);
    const Eigen::Matrix2d before = stress_tensor(s, x);
    Eigen::VectorXd moved = x;
    const Particle& p = s.particles[3];
    for (int v = p.first; v < p.first + p.count; ++v)
        moved.segment<2>(2 * v) += Eigen::Vector2d(8.0, -7.0); // one box vector
    const Eigen::Matrix2d after = stress_tensor(s, moved);
    // Only round-off: the force moments are evaluated at coordinates differing by a box vector.
    CHECK_CLOSE((after - before).norm(), 0.0, (Tolerance{0, 1e-12 * std::max(1.0, before.norm())}));
}

TEST_CASE(
    "per-particle stresses weighted by their areas sum to the total stress [DPM eq. (9.27) and its sum rule]")
{
    Rng rng(21);
    Eigen::VectorXd x;
    const DpmSystem s = random_periodic(InteractionKind::rough, rng, x);
    const std::vector<Eigen::Matrix2d> parts = particle_stresses(s, x);
    const std::vector<double> areas = particle_areas(s, x);
    Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
    for (std::size_t m = 0; m < parts.size(); ++m)
        sum += areas[m] * parts[m];
    const Eigen::Matrix2d total = s.box->prod() * stress_tensor(s, x);
    // An identity (h_{mu i,beta j} + h_{beta j,mu i} = r): round-off of sums over ~100 contact terms.
    CHECK_CLOSE((sum - total).norm(), 0.0, (Tolerance{0, 1e-12 * total.norm()}));
    CHECK(total.norm() > 0);
}
