// Rough disks of DPM section 9.4.2 (rigid regular polygons with rough vertices, eqs. 9.3-9.4): the stress of
// the rigid packing (eq. 9.26 with the rigid-body constraint forces) equals the strain derivative of the
// energy when the particle centres move affinely and the shapes are kept, and the rigid-body FIRE keeps
// every shape exactly while it reaches force and torque balance.
#include "core/rng.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/relax/rigid.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// Random overlapping rigid 12-gons (vertex diameter 1, edges 0.85) in a periodic box.
DpmSystem random_rough_disks(Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.box = Eigen::Vector2d(14.0, 13.0);
    const double r = 0.85 / (2 * std::sin(std::numbers::pi / 12));
    for (int m = 0; m < 20; ++m) {
        const Eigen::Vector2d c(rng.uniform(0, 14), rng.uniform(0, 13));
        s.add_particle(regular_polygon(12, (m % 2 ? 1.4 : 1.0) * r, c, rng.uniform(0, 2 * std::numbers::pi)),
                       1.0, ShapeParameters{}, x);
    }
    return s;
}

// U after stretching the centres (and the box) along `axis` by 1 + e, shapes kept.
double strained_energy(DpmSystem s, Eigen::VectorXd x, int axis, double e)
{
    for (const Particle& p : s.particles) {
        auto v = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const double shift = e * v.row(axis).mean();
        v.row(axis).array() += shift;
    }
    (*s.box)(axis) *= 1 + e;
    return total_energy(s, x, nullptr, nullptr);
}

} // namespace

TEST_CASE("rigid rough polygons: stress = -(1/A) dU/d(strain) of the centres [DPM eq. (9.26), rough disks of "
          "sec. 9.4.2]")
{
    Rng rng(3);
    Eigen::VectorXd x;
    const DpmSystem s = random_rough_disks(rng, x);
    const Eigen::Matrix2d stress = rigid_stress_tensor(s, x);
    REQUIRE(total_energy(s, x, nullptr, nullptr) > 0);
    for (int axis : {0, 1}) {
        const double e = 1e-6;
        const double derivative =
            (strained_energy(s, x, axis, e) - strained_energy(s, x, axis, -e)) / (2 * e);
        // Central difference at e = 1e-6: truncation ~1e-12 U, round-off ~1e-10 U; 1e-7 relative is far
        // above both and far below the vertex-virial term the rigid correction replaces (O(1) here).
        CHECK_CLOSE(-s.box->prod() * stress(axis, axis), derivative, (Tolerance{1e-7, 1e-9}));
    }
    // Non-vacuous: the plain vertex virial differs (it would be the stress of deformable particles).
    const double plain = -s.box->prod() * stress_tensor(s, x)(0, 0);
    const double derivative = (strained_energy(s, x, 0, 1e-6) - strained_energy(s, x, 0, -1e-6)) / 2e-6;
    CHECK(std::abs(plain - derivative) > 1e-3 * std::abs(derivative));
}

TEST_CASE("rigid-body FIRE keeps every polygon's shape and balances forces and torques [DPM sec. 9.4.2]")
{
    Rng rng(4);
    Eigen::VectorXd x;
    const DpmSystem s = random_rough_disks(rng, x);
    const Eigen::VectorXd before = x;
    FireOptions fire;
    fire.dt_max = 0.3;
    fire.dt_initial = 0.05;
    fire.force_tolerance = 1e-10;
    const FireResult r = relax_rigid_fire(s, x, fire);
    REQUIRE(r.converged);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    total_energy(s, x, &g, nullptr);
    double shape_change = 0, moved = 0, largest_net = 0;
    for (const Particle& p : s.particles) {
        const auto a = before.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const auto b = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        for (int i = 0; i < p.count; ++i)
            for (int j = 0; j < p.count; ++j)
                shape_change = std::max(
                    shape_change, std::abs((a.col(i) - a.col(j)).norm() - (b.col(i) - b.col(j)).norm()));
        moved = std::max(moved, (a - b).norm());
        const auto f = g.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const Eigen::Vector2d c = b.rowwise().mean();
        double torque = 0;
        for (int i = 0; i < p.count; ++i)
            torque += (b(0, i) - c.x()) * f(1, i) - (b(1, i) - c.y()) * f(0, i);
        largest_net = std::max({largest_net, f.rowwise().sum().norm(), std::abs(torque)});
    }
    // Rotations are applied exactly: only round-off changes the vertex distances.
    CHECK_CLOSE(shape_change, 0.0, (Tolerance{0, 1e-12}));
    CHECK(moved > 0.1); // the overlapping start had to move
    // FIRE's rms generalised force < 1e-10 per coordinate: net force and torque / R of each body below
    // sqrt(3 N) x 1e-10 ~ 1e-9, torque below that times R ~ 2.
    CHECK_CLOSE(largest_net, 0.0, (Tolerance{0, 1e-8}));
}
