// DPM Fig. 9.5(c, d): a mode of a packing of deformable particles split per particle into rigid translation,
// rigid rotation and deformation (dpm/analysis/modes.hpp decompose_mode). Fields built from known parts must
// come back with exactly their shares (2D, and 3D as used for the softest mode of Fig. 9.15d-f). The
// quartic-mode test of Fig. 9.14(c) is in mode_energy.cpp.
#include "dpm/analysis/modes.hpp"
#include "dpm/system/mesh3d.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// The unit fields of pure translation, rotation and deformation come back with share 1 in their own part
// and 0 in the others; a mixture a T + b R + c D of them with shares a^2, b^2, c^2.
template <class System>
void check_shares(const System& system, const Eigen::VectorXd& x, const Eigen::VectorXd& translation,
                  const Eigen::VectorXd& rotation, const Eigen::VectorXd& deformation, Tolerance exact)
{
    const ModeParts t_only = decompose_mode(system, x, translation);
    const ModeParts r_only = decompose_mode(system, x, rotation);
    const ModeParts d_only = decompose_mode(system, x, deformation);
    CHECK_CLOSE(t_only.translation, 1.0, exact);
    CHECK_CLOSE(t_only.rotation + t_only.deformation, 0.0, exact);
    CHECK_CLOSE(r_only.rotation, 1.0, exact);
    CHECK_CLOSE(r_only.translation + r_only.deformation, 0.0, exact);
    CHECK_CLOSE(d_only.deformation, 1.0, exact);
    CHECK_CLOSE(d_only.translation + d_only.rotation, 0.0, exact);
    const double a = 0.5, b = 0.3, d = std::sqrt(1 - a * a - b * b);
    const ModeParts mixed = decompose_mode(system, x, a * translation + b * rotation + d * deformation);
    CHECK_CLOSE(mixed.translation, a * a, exact);
    CHECK_CLOSE(mixed.rotation, b * b, exact);
    CHECK_CLOSE(mixed.deformation, d * d, exact);
}

// Two particles: a regular 10-gon (irregularly rotated, off-centre) and a disk.
struct TwoParticles
{
    DpmSystem system;
    Eigen::VectorXd x;
    TwoParticles()
    {
        system.add_particle(regular_polygon(10, 2.0, Eigen::Vector2d(3.0, -1.0), 0.3), 1.0, ShapeParameters{},
                            x);
        Eigen::Matrix2Xd disk(2, 1);
        disk << 8.0, 2.0;
        system.add_particle(disk, 1.0, ShapeParameters{}, x);
    }
};

} // namespace

TEST_CASE(
    "mode decomposition returns the shares of known translation, rotation and deformation [DPM Fig. 9.5]")
{
    const TwoParticles t;
    const Eigen::Vector2d c(3.0, -1.0);
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(t.x.size()), rotation = translation,
                    deformation = translation;
    for (int i = 0; i < 10; ++i) {
        const Eigen::Vector2d arm = t.x.segment<2>(2 * i) - c;
        translation.segment<2>(2 * i) = Eigen::Vector2d(0.6, -0.8);
        rotation.segment<2>(2 * i) = Eigen::Vector2d(-arm.y(), arm.x());
        deformation.segment<2>(2 * i) =
            (i % 2 == 0 ? 1.0 : -1.0) * arm; // alternate in/out: no net t or omega
    }
    translation.segment<2>(20) = Eigen::Vector2d(1.0, 0.5); // the disk: translation only
    translation.normalize();
    rotation.normalize();
    deformation.normalize();
    // Sums of O(20) terms of order 1: round-off of a few tens of ulp.
    check_shares(t.system, t.x, translation, rotation, deformation, Tolerance{0, 100 * round_off});
}

TEST_CASE("3D mode decomposition returns the shares of known translation, rotation and deformation "
          "[DPM Fig. 9.5, Fig. 9.15d-f]")
{
    // An icosahedron stretched along z (an anisotropic inertia tensor, so that the least-squares rotation
    // needs the full tensor), tilted and off-centre, and a one-vertex particle.
    DpmSystem3d s;
    Eigen::VectorXd x;
    s.meshes.push_back(mesh_from_name("icosahedron"));
    TriangleMesh point;
    point.vertices = Eigen::Matrix3Xd::Zero(3, 1);
    s.meshes.push_back(point);
    const Eigen::Vector3d c(3.0, -1.0, 0.5);
    const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()).matrix();
    const Eigen::Matrix3Xd body =
        tilt * Eigen::Vector3d(2.0, 2.0, 3.0).asDiagonal() * s.meshes[0].vertices; // centred: vertices +-v
    s.add_particle(0, body.colwise() + c, 1.0, ShapeParameters3d{}, x);
    s.add_particle(1, Eigen::Vector3d(8.0, 2.0, -1.0), 1.0, ShapeParameters3d{}, x);
    const int n = static_cast<int>(body.cols());
    const Eigen::Vector3d omega(0.3, -0.5, 0.8);
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(x.size()), rotation = translation,
                    deformation = translation;
    for (int i = 0; i < n; ++i) {
        translation.segment<3>(3 * i) = Eigen::Vector3d(0.6, -0.8, 0.2);
        rotation.segment<3>(3 * i) = omega.cross(Eigen::Vector3d(body.col(i)));
        deformation.segment<3>(3 * i) = body.col(i); // breathing: sum r_i = 0 and sum r_i x r_i = 0
    }
    translation.segment<3>(3 * n) = Eigen::Vector3d(1.0, 0.5, -0.3); // the point: translation only
    translation.normalize();
    rotation.normalize();
    deformation.normalize();
    // Sums of O(40) terms of order 1 and a 3 x 3 solve: round-off of a few hundred ulp.
    check_shares(s, x, translation, rotation, deformation, Tolerance{0, 1000 * round_off});
}

TEST_CASE("the zero modes beyond the uniform translations are located on the particle that carries them, "
          "in any basis [DPM Fig. 9.15b]")
{
    // Three icosahedra (12 vertices each, 36 in all). Zero modes: the 3 uniform translations of the
    // packing, the rigid rotation of particle 1 about an axis through its centre (a particle free to turn
    // about the line through its contacts) and the 3 rigid translations of particle 2 (a rattler's), mixed
    // by a random orthogonal matrix: the result must not depend on the basis.
    DpmSystem3d s;
    Eigen::VectorXd x;
    s.meshes.push_back(mesh_from_name("icosahedron"));
    const Eigen::Matrix3Xd& unit = s.meshes[0].vertices;
    const Eigen::Vector3d centres[] = {{0, 0, 0}, {3, 0.5, -1}, {-2, 2.5, 1}};
    for (const Eigen::Vector3d& c : centres)
        s.add_particle(0, unit.colwise() + c, 1.0, ShapeParameters3d{}, x);
    const Eigen::Index n = x.size();
    Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(n, 7);
    for (Eigen::Index i = 0; i < n; ++i)
        zero(i, i % 3) = 1.0; // uniform translations
    const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -1.0, 0.4).normalized();
    for (int v = 0; v < 12; ++v) {
        zero.block<3, 1>(3 * (12 + v), 3) = axis.cross(Eigen::Vector3d(unit.col(v)));
        for (int d = 0; d < 3; ++d)
            zero(3 * (24 + v) + d, 4 + d) = 1.0;
    }
    const Eigen::MatrixXd orthonormal =
        Eigen::HouseholderQR<Eigen::MatrixXd>(zero).householderQ() * Eigen::MatrixXd::Identity(n, 7);
    const Eigen::MatrixXd mixing =
        Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(7, 7)).householderQ();
    int dimension = 0;
    const std::vector<ModeParts> parts = nontrivial_zero_mode_parts(s, x, orthonormal * mixing, dimension);
    CHECK(dimension == 4);
    const Tolerance exact{0, 1000 * round_off};
    // Particle 1: its rotation, one of 4 basis vectors. Particle 2: a translation e of it (norm 1) made
    // orthogonal to the uniform one t has e.t = sqrt(12/36), norm^2 1 - 1/3, and per vertex (1 -
    // 1/3)/sqrt(12) on particle 2 and -1/(6 sqrt(3)) on the others: shares 2/3 on particle 2 and 1/6 on each
    // other particle, times 3 of the 4 basis vectors.
    CHECK_CLOSE(parts[1].rotation, 0.25, exact);
    CHECK_CLOSE(parts[2].translation, 3 * (2.0 / 3) / 4, exact);
    CHECK_CLOSE(parts[0].translation, 3 * (1.0 / 6) / 4, exact);
    CHECK_CLOSE(parts[1].translation, 3 * (1.0 / 6) / 4, exact);
    for (const ModeParts& p : parts)
        CHECK_CLOSE(p.deformation, 0.0, exact);
    CHECK_CLOSE(parts[0].rotation + parts[2].rotation, 0.0, exact);
}
