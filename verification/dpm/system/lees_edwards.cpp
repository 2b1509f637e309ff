// Lees-Edwards boundaries of DPM section 9.4.3: the sheared periodic images are consistent. (1) The energy
// does not change when a particle is moved by a sheared box vector (gamma L_y, L_y) or by (L_x, 0), nor when
// the strain grows by a full box shear L_x/L_y (the lattice of images is the same); (2) the virial shear
// stress of eq. (9.26) is the strain derivative of the energy under the simple shear x' = x + dgamma y with
// the Lees-Edwards offset: Sigma_yx = -(1/A) dU/dgamma, for rough and smooth interactions, with contacts
// across the sheared boundary.
#include "core/rng.hpp"
#include "dpm/analysis/stress.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// Dense random periodic system of deformable hexagons under a Lees-Edwards strain of 0.23.
DpmSystem random_sheared(InteractionKind kind, Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = kind;
    s.box = Eigen::Vector2d(8.0, 7.0);
    s.lees_edwards_strain = 0.23;
    ShapeParameters shape;
    shape.ka = 0.9;
    shape.a0 = 1.2;
    shape.kl = 2.0;
    shape.l0 = 0.8;
    shape.kb = 0.3;
    shape.theta0 = 2 * std::numbers::pi / 6;
    for (int m = 0; m < 22; ++m) {
        const Eigen::Vector2d c(rng.uniform(0, 8), rng.uniform(0, 7));
        Eigen::Matrix2Xd v = regular_polygon(6, 0.75, c, rng.uniform(0, 2 * std::numbers::pi));
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.08 * rng.uniform(-1, 1);
        s.add_particle(v, rng.uniform(0.6, 0.9), shape, x);
    }
    return s;
}

double energy_after_shear(DpmSystem s, Eigen::VectorXd x, double dgamma)
{
    shear_packing(s, x, dgamma);
    return total_energy(s, x, nullptr, nullptr);
}

} // namespace

TEST_CASE(
    "Lees-Edwards images: energy invariant under sheared box vectors and a full box shear [DPM sec. 9.4.3]")
{
    Rng rng(11);
    Eigen::VectorXd x;
    DpmSystem s = random_sheared(InteractionKind::rough, rng, x);
    const double u = total_energy(s, x, nullptr, nullptr);
    REQUIRE(total_energy(s, x, nullptr, nullptr, interaction_part) > 0);
    const double L_x = s.box->x(), L_y = s.box->y(), gamma = s.lees_edwards_strain;
    for (const Eigen::Vector2d& shift :
         {Eigen::Vector2d(gamma * L_y, L_y), Eigen::Vector2d(-gamma * L_y, -L_y), Eigen::Vector2d(L_x, 0),
          Eigen::Vector2d(L_x + gamma * L_y, L_y)}) {
        for (int m : {0, 5, 13}) {
            Eigen::VectorXd moved = x;
            const Particle& p = s.particles[m];
            for (int v = p.first; v < p.first + p.count; ++v)
                moved.segment<2>(2 * v) += shift;
            // Same interaction terms at coordinates differing by an image vector: round-off only.
            CHECK_CLOSE(total_energy(s, moved, nullptr, nullptr), u, (Tolerance{1e-12, 1e-14}));
        }
    }
    s.lees_edwards_strain += L_x / L_y; // the offset grows by one box length: the same image lattice
    CHECK_CLOSE(total_energy(s, x, nullptr, nullptr), u, (Tolerance{1e-12, 1e-14}));
    // Non-vacuous: an offset of half a box length changes the contacts across the boundary.
    s.lees_edwards_strain += 0.5 * L_x / L_y;
    CHECK(std::abs(total_energy(s, x, nullptr, nullptr) - u) > 1e-6 * u);
}

TEST_CASE(
    "virial shear stress = -(1/A) dU/dgamma under Lees-Edwards simple shear [DPM eq. (9.26), sec. 9.4.3]")
{
    Rng rng(12);
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        for (int sample = 0; sample < 2; ++sample) {
            Eigen::VectorXd x;
            const DpmSystem s = random_sheared(kind, rng, x);
            const double e = 1e-6;
            const double derivative = (energy_after_shear(s, x, e) - energy_after_shear(s, x, -e)) / (2 * e);
            const Eigen::Matrix2d stress = stress_tensor(s, x);
            CAPTURE(sample);
            // Central difference at 1e-6: truncation ~1e-12 U, round-off ~1e-10 U; 1e-7 relative is far from
            // both and from a missing offset (which changes the contacts across the boundary by O(1)).
            CHECK_CLOSE(-s.box->prod() * stress(1, 0), derivative, (Tolerance{1e-7, 1e-9}));
        }
    }
}
