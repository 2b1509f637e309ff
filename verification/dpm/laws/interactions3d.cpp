// DPM section 9.3.2 in 3D: rough vertex-vertex repulsion between triangulated particles (eqs. 9.3-9.4 with
// vertex spheres of diameter sigma) in a periodic cubic box with the minimum image. Forces are minus the
// gradient, the Hessian the derivative of the forces (finite differences on random overlapping
// configurations, some across the box boundary); contact forces sum to zero (Newton's third law); one
// contact has the closed form k_c/2 (sigma_mb - r)^2; a whole-box translation by L leaves U unchanged.
#include "core/rng.hpp"
#include "dpm/system/system3d.hpp"
#include "support/derivatives.hpp"
#include "support/tolerance.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_against_central_differences;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// Three randomly displaced icosahedra (circumradius 1) with random vertex diameters, overlapping, in a
// periodic box of side 5 placed so that the cluster straddles the boundary x = 0 (no shape energy).
DpmSystem3d random_overlapping3d(Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem3d s;
    s.kc = rng.uniform(0.5, 2.0);
    s.box = 5.0;
    s.meshes.push_back(icosahedron_mesh());
    for (int m = 0; m < 3; ++m) {
        const Eigen::Vector3d centre(1.5 * m - 1.0, rng.uniform(-0.3, 0.3) + 2.5,
                                     rng.uniform(-0.3, 0.3) + 2.5);
        Eigen::Matrix3Xd v = s.meshes[0].vertices.colwise() + centre;
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.15 * rng.uniform(-1, 1); // seeded: independent of test order
        s.add_particle(0, v, rng.uniform(0.4, 0.9), ShapeParameters3d{}, x);
    }
    return s;
}

} // namespace

TEST_CASE(
    "3D rough contacts: forces = -grad U, Hessian = d(grad U), Newton's third law [DPM eqs. (9.3)-(9.4)]")
{
    Rng rng(7);
    int contacts_seen = 0;
    for (int sample = 0; sample < 6; ++sample) {
        CAPTURE(sample);
        Eigen::VectorXd x;
        const DpmSystem3d s = random_overlapping3d(rng, x);
        const Eigen::Index dofs = x.size();
        Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
        const double energy = interaction_energy3d(s, x, &g, &h);
        CHECK_CLOSE(interaction_energy3d(s, x, nullptr, nullptr), energy, (Tolerance{10 * round_off, 0}));
        check_against_central_differences(
            [&](const Eigen::VectorXd& y, Eigen::VectorXd* gy, Eigen::MatrixXd* hy) {
                return interaction_energy3d(s, y, gy, hy);
            },
            x, g, h);
        const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
        CHECK_CLOSE(g.reshaped(3, dofs / 3).rowwise().sum().norm(), 0.0,
                    (Tolerance{0, 1e3 * round_off * g_scale}));
        // Periodicity: moving one particle by a box vector changes nothing (minimum image per vertex pair).
        Eigen::VectorXd shifted = x;
        const Particle3d& first = s.particles[0];
        for (int v = first.first; v < first.first + first.count; ++v)
            shifted(3 * v) += *s.box;
        CHECK_CLOSE(interaction_energy3d(s, shifted, nullptr, nullptr), energy,
                    (Tolerance{1e3 * round_off, 1e3 * round_off}));
        contacts_seen += energy > 0;
    }
    CHECK(contacts_seen == 6); // every sample overlaps: the checks are not vacuous
}

TEST_CASE("one 3D vertex contact across the periodic boundary: U = k_c/2 (sigma_mb - r)^2 [DPM eq. (9.4)]")
{
    // Two icosahedra (circumradius 1) on the x axis with one vertex each on the axis; their tips 0.3 apart
    // through the boundary x = 0 = L. sigma_mb = (0.5 + 0.9)/2 = 0.7; the next vertex pairs are farther
    // than 1.2 apart, so exactly one contact.
    DpmSystem3d s;
    s.kc = 1.7;
    s.box = 10.0;
    TriangleMesh ico = icosahedron_mesh();
    const Eigen::Vector3d tip = ico.vertices.col(0).normalized();
    const Eigen::Matrix3d to_x =
        Eigen::Quaterniond::FromTwoVectors(tip, Eigen::Vector3d::UnitX()).toRotationMatrix();
    ico.vertices = to_x * ico.vertices; // vertex 0 on +x
    s.meshes.push_back(ico);
    Eigen::VectorXd x;
    const Eigen::Vector3d left(10.0 - 1.15, 5, 5),
        right(1.15, 5, 5); // tips at 9.85 and 0.15: 0.3 apart through x = L
    const Eigen::Matrix3d flip = Eigen::Vector3d(-1, -1, 1).asDiagonal(); // rotation by pi about z
    s.add_particle(0, ico.vertices.colwise() + left, 0.5, ShapeParameters3d{}, x);
    s.add_particle(0, (flip * ico.vertices).colwise() + right, 0.9, ShapeParameters3d{}, x);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    const double u = interaction_energy3d(s, x, &g, nullptr);
    const double r = 0.3, sigma = 0.7;
    // r is a difference of coordinates of size L = 10: its round-off is ~L eps, so U carries k_c (sigma - r)
    // times that and the force k_c times that (a few units each).
    const Tolerance coordinate_round_off{0, 10 * 1.7 * 10 * round_off};
    CHECK_CLOSE(u, 0.5 * 1.7 * (sigma - r) * (sigma - r), coordinate_round_off);
    // The force on the left tip points away from the right one (-x), magnitude k_c (sigma - r).
    CHECK_CLOSE(-g(0), -1.7 * (sigma - r), coordinate_round_off);
    const std::vector<int> contacts = contact_counts3d(s, x);
    CHECK(contacts[0] == 1);
    CHECK(contacts[1] == 1);
}
