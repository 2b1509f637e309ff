// Lees-Edwards boundaries of DPM section 9.4.3 in 3D (x sheared along y in a periodic cube): the sheared
// images are consistent. (1) The energy does not change when a particle is moved by a sheared box vector
// (gamma L, L, 0), by (L, 0, 0) or (0, 0, L), nor when the strain grows by a full box shear of 1 (the same
// lattice of images); (2) the cell list on the sheared coordinates finds every contact (against a sum over
// all vertex pairs); (3) the virial shear stress of the 3D analogue of eq. (9.26) is the strain derivative of
// the energy under x' = x + dgamma y with the Lees-Edwards offset, Sigma_yx = -(1/V) dU/dgamma, with shape
// forces of each model of Table 9.1 and contacts across the sheared boundary.
#include "core/rng.hpp"
#include "dpm/protocols/single_particle3d.hpp"
#include "dpm/system/system3d.hpp"
#include "support/jammed3d.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::random_sheared3d;
using softgrain::verification::Tolerance;

namespace {

double energy_after_shear(DpmSystem3d s, Eigen::VectorXd x, double dgamma)
{
    shear_packing3d(s, x, dgamma);
    return total_energy3d(s, x, nullptr, nullptr);
}

// Eq. (9.4) summed over every vertex pair of different particles at its Lees-Edwards minimum image, without
// a cell list: the reference for the cell list on sheared coordinates.
double all_pairs_interaction(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    double energy = 0;
    for (std::size_t a = 0; a < s.particles.size(); ++a)
        for (std::size_t b = a + 1; b < s.particles.size(); ++b) {
            const Particle3d &p = s.particles[a], &q = s.particles[b];
            const double sigma = 0.5 * (p.sigma + q.sigma);
            for (int i = p.first; i < p.first + p.count; ++i)
                for (int j = q.first; j < q.first + q.count; ++j) {
                    const double r = s.image(x.segment<3>(3 * j) - x.segment<3>(3 * i)).norm();
                    if (r < sigma) energy += 0.5 * s.kc * (sigma - r) * (sigma - r);
                }
        }
    return energy;
}

} // namespace

TEST_CASE("3D Lees-Edwards images: energy invariant under sheared box vectors and a full box shear [DPM sec. "
          "9.4.3]")
{
    Rng rng(21);
    Eigen::VectorXd x;
    DpmSystem3d s = random_sheared3d(ShapeModel::shell, rng, x);
    const double u = total_energy3d(s, x, nullptr, nullptr);
    REQUIRE(interaction_energy3d(s, x, nullptr, nullptr) > 0);
    const double L = *s.box, gamma = s.lees_edwards_strain;
    for (const Eigen::Vector3d& shift :
         {Eigen::Vector3d(gamma * L, L, 0), Eigen::Vector3d(-gamma * L, -L, 0), Eigen::Vector3d(L, 0, 0),
          Eigen::Vector3d(0, 0, -L), Eigen::Vector3d(L + gamma * L, L, L)}) {
        for (int m : {0, 3, 6}) {
            Eigen::VectorXd moved = x;
            const Particle3d& p = s.particles[m];
            for (int v = p.first; v < p.first + p.count; ++v)
                moved.segment<3>(3 * v) += shift;
            CAPTURE(m);
            // Same contact terms at coordinates differing by an image vector: round-off only.
            CHECK_CLOSE(total_energy3d(s, moved, nullptr, nullptr), u, (Tolerance{1e-12, 1e-14}));
        }
    }
    s.lees_edwards_strain += 1.0; // the offset grows by one box length: the same image lattice
    CHECK_CLOSE(total_energy3d(s, x, nullptr, nullptr), u, (Tolerance{1e-12, 1e-14}));
    // Non-vacuous: an offset of half a box length changes the contacts across the boundary y = 0.
    s.lees_edwards_strain += 0.5;
    CHECK(std::abs(total_energy3d(s, x, nullptr, nullptr) - u) > 1e-6 * u);
}

TEST_CASE("3D cell list on sheared coordinates finds every Lees-Edwards contact [DPM eq. (9.4), sec. 9.4.3]")
{
    Rng rng(22);
    for (int sample = 0; sample < 3; ++sample) {
        Eigen::VectorXd x;
        DpmSystem3d s = random_sheared3d(ShapeModel::shell, rng, x);
        s.lees_edwards_strain = rng.uniform(-0.4, 0.4);
        const double reference = all_pairs_interaction(s, x);
        REQUIRE(reference > 0);
        CAPTURE(sample);
        // The same terms summed in another order: round-off only; a missed contact changes U by O(1e-3 U).
        CHECK_CLOSE(interaction_energy3d(s, x, nullptr, nullptr), reference, (Tolerance{1e-12, 0}));
    }
}

TEST_CASE("3D virial shear stress = -(1/V) dU/dgamma under Lees-Edwards simple shear [DPM eq. (9.26) in 3D, "
          "sec. 9.4.3]")
{
    Rng rng(23);
    for (ShapeModel model : {ShapeModel::shell, ShapeModel::floppy, ShapeModel::surface_tension}) {
        Eigen::VectorXd x;
        const DpmSystem3d s = random_sheared3d(model, rng, x);
        const double e = 1e-6;
        const double derivative = (energy_after_shear(s, x, e) - energy_after_shear(s, x, -e)) / (2 * e);
        const Eigen::Matrix3d stress = stress_tensor3d(s, x);
        CAPTURE(static_cast<int>(model));
        // Central difference at 1e-6: truncation ~1e-12 U, round-off ~1e-10 U; 1e-7 relative is far from both
        // and from a missing offset (which changes the contacts across the boundary by O(1)).
        CHECK_CLOSE(-std::pow(*s.box, 3) * stress(1, 0), derivative, (Tolerance{1e-7, 1e-9}));
    }
}
