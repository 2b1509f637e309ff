// A periodic packing tiled k times along each axis (replicate_periodic_packing, scale_packing.hpp) is the
// same infinite packing in a larger box, so:
//   * its energy is k^Dim times the old one, its gradient is the old one repeated in every copy, its stress
//     and its contact counts per particle are the old ones, also under a Lees-Edwards strain;
//   * its dynamical matrix (eq. 9.28) holds the old one as its zero-wave-vector Bloch block: every old mode,
//     tiled, is a mode of the new packing with the same eigenvalue, and so the lowest eigenvalues that the
//     sparse solver (sparse_modes.hpp) finds in the tiling include the old lowest ones.
//
// Round-off: the copies are the old vertices plus a lattice vector, so every term differs by the round-off
// of coordinates up to k L from the origin. The largest is the volume of eq. (9.2) (and the area of eq. 9.1
// in 2D), summed from products of absolute coordinates: its round-off grows as (|r| / particle size)^2,
// at most (2 x 4.2 x 1.3 / 1)^2 ~ 100 here, times the 20 faces of an icosahedron, ~ 2e3 eps of the terms.
// The totals then sum k^Dim times as many terms in another order. Hence relative bounds of 1e4 eps on the
// energy (a sum of non-negative terms), on the gradient and on the stress (against their largest entry).
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/system/scale_packing.hpp"
#include "support/jammed3d.hpp"
#include "support/packings.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::polished_packing2d;
using softgrain::verification::polished_packing3d;
using softgrain::verification::random_sheared3d;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

constexpr double tiling_round_off = 1e4 * round_off;

// The gradient of the tiling against the old one in each of its `copies` blocks.
void check_tiled_gradient(const Eigen::VectorXd& old_gradient, const Eigen::VectorXd& tiled_gradient,
                          int copies)
{
    const Eigen::Index n = old_gradient.size();
    REQUIRE(tiled_gradient.size() == copies * n);
    const double scale = old_gradient.cwiseAbs().maxCoeff();
    REQUIRE(scale > 0);
    double largest = 0;
    for (int c = 0; c < copies; ++c)
        largest = std::max(largest, (tiled_gradient.segment(c * n, n) - old_gradient).cwiseAbs().maxCoeff());
    MESSAGE("max|g_tiled - g| / max|g| = " << largest / scale);
    CHECK(largest <= tiling_round_off * scale);
}

template <class Matrix>
void check_same_stress(const Matrix& old_stress, const Matrix& tiled_stress)
{
    const double scale = old_stress.cwiseAbs().maxCoeff();
    REQUIRE(scale > 0);
    CHECK((tiled_stress - old_stress).cwiseAbs().maxCoeff() <= tiling_round_off * scale);
}

} // namespace

TEST_CASE("3D packing tiled 2 x 2 x 2 under Lees-Edwards: 8 x the energy, the same forces, stress and "
          "contacts")
{
    Rng rng(7);
    Eigen::VectorXd x;
    DpmSystem3d s = random_sheared3d(ShapeModel::shell, rng, x); // box 4.2, gamma 0.23, many contacts
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    const double energy = total_energy3d(s, x, &g, nullptr);
    const Eigen::Matrix3d stress = stress_tensor3d(s, x);
    const std::vector<int> contacts = contact_counts3d(s, x);
    const auto particles = s.particles.size();

    DpmSystem3d tiled = s;
    Eigen::VectorXd y = x;
    replicate_periodic_packing<3>(tiled, y, 2);
    REQUIRE(tiled.particles.size() == 8 * particles);
    CHECK(*tiled.box == 2 * *s.box);
    CHECK(tiled.lees_edwards_strain == s.lees_edwards_strain);
    Eigen::VectorXd gy = Eigen::VectorXd::Zero(y.size());
    CHECK_CLOSE(total_energy3d(tiled, y, &gy, nullptr), 8 * energy, (Tolerance{tiling_round_off, 0}));
    check_tiled_gradient(g, gy, 8);
    check_same_stress(stress, stress_tensor3d(tiled, y));
    const std::vector<int> tiled_contacts = contact_counts3d(tiled, y);
    CHECK(std::accumulate(contacts.begin(), contacts.end(), 0) > 0);
    for (std::size_t m = 0; m < tiled_contacts.size(); ++m)
        CHECK(tiled_contacts[m] == contacts[m % particles]);
}

TEST_CASE("2D packing tiled 3 x 3 under Lees-Edwards: 9 x the energy, the same forces and stress")
{
    JamResult j = polished_packing2d(JamModel::shell, 6, 2);
    shear_packing(j.system, j.x, 0.3); // off equilibrium: forces to compare
    Eigen::VectorXd g = Eigen::VectorXd::Zero(j.x.size());
    const double energy = total_energy(j.system, j.x, &g, nullptr);
    DpmSystem tiled = j.system;
    Eigen::VectorXd y = j.x;
    replicate_periodic_packing<2>(tiled, y, 3);
    REQUIRE(tiled.particles.size() == 9 * j.system.particles.size());
    CHECK(*tiled.box == 3 * *j.system.box);
    Eigen::VectorXd gy = Eigen::VectorXd::Zero(y.size());
    CHECK_CLOSE(total_energy(tiled, y, &gy, nullptr), 9 * energy, (Tolerance{tiling_round_off, 0}));
    check_tiled_gradient(g, gy, 9);
    check_same_stress(stress_tensor(j.system, j.x), stress_tensor(tiled, y));
}

// Bloch: with the tiled mode v = (e, e, ..., e)/sqrt(8) of an old mode (lambda, e), M' v = lambda v, to the
// round-off of the entries: with an error delta <= 1e4 eps max|M| per entry (as above) and at most w
// non-zeros per row, ||Delta v|| <= ||Delta||_2 <= sqrt(||Delta||_1 ||Delta||_inf) <= w delta; plus the
// dense eigensolver's residual n eps lambda_max of the old mode. And the
// sparse solver, asked for the K lowest modes of the tiling, K its eigenvalues below tau (midway between the
// 12th and 13th old eigenvalues; counted by Sylvester's inertia, eigenvalues_below), finds every one of the
// 12 lowest old eigenvalues among them, within its bound (2 n eps + 1e-12) lambda_max
// (verification/dpm/analysis/sparse_modes.cpp): what dpm.bench's `replicate` with `lowest_modes` computes.
TEST_CASE("the modes of a jammed 3D packing, tiled, are modes of its 2 x 2 x 2 tiling [eq. 9.28, Bloch]")
{
    const Jam3dResult j = polished_packing3d(4, 1);
    const Eigen::Index n = j.x.size();
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    total_energy3d(j.system, j.x, nullptr, &m);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> old_modes(m);
    const Eigen::VectorXd& lambda = old_modes.eigenvalues();

    DpmSystem3d tiled = j.system;
    Eigen::VectorXd y = j.x;
    replicate_periodic_packing<3>(tiled, y, 2);
    const Eigen::SparseMatrix<double> big = sparse_dynamical_matrix3d(tiled, y);
    Eigen::Index widest = 0;
    for (Eigen::Index c = 0; c < big.outerSize(); ++c)
        widest = std::max(widest, Eigen::Index(big.outerIndexPtr()[c + 1] - big.outerIndexPtr()[c]));
    const double residual = widest * tiling_round_off * m.cwiseAbs().maxCoeff() +
                            static_cast<double>(n) * round_off * lambda(n - 1);
    MESSAGE("at most " << widest << " non-zeros per row; allowed residual " << residual);
    constexpr int lowest = 12;
    for (int k = 0; k < lowest; ++k) {
        CAPTURE(k);
        const Eigen::VectorXd v = old_modes.eigenvectors().col(k).replicate(8, 1) / std::sqrt(8.0);
        CHECK((big * v - lambda(k) * v).norm() <= residual);
    }
    const int below = eigenvalues_below(big, 0.5 * (lambda(lowest - 1) + lambda(lowest)));
    MESSAGE("the tiling has " << below << " eigenvalues below the old packing's " << lowest + 1 << "th");
    REQUIRE(below >= lowest);
    REQUIRE(below < big.rows());
    const LowestModes found = lowest_modes(big, below);
    const double bound = (2 * static_cast<double>(big.rows()) * round_off + 1e-12) * lambda(n - 1);
    for (int k = 0; k < lowest; ++k) {
        CAPTURE(k);
        CHECK((found.spectrum.eigenvalues.array() - lambda(k)).abs().minCoeff() <= bound);
    }
}
