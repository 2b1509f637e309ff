// The sparse path of the 3D jamming protocol's Hessian (packing_hessian3d.hpp: FIRE's time step, the Newton
// polish before a spectrum, the saddle test) against the dense path on a small packing where both run,
// forced through HessianStorage (below dense_hessian_limit3d the protocol itself takes the dense path).
//
// (a) lambda_max: Spectra's Lanczos stops at a relative residual 1e-12, which bounds the error of an extreme
//     eigenvalue; the dense eigensolver's is n eps ||M|| (6e-14 relative at n = 288): relative 1e-10.
// (b) The polish: both must reach polish_for_modes' largest force 1e-14 P-unit. Their end points differ by
//     the residual forces over the stiffness, f / lambda_min^+ (1e-14 / 1e-4 in the units of the packing),
//     and by the zero modes the two steps treat differently (the pseudo-inverse leaves them out, the
//     regularised step takes g_k / mu along them, g_k the round-off of the force's component): 1e-8 sigma.
// (c) The lowest eigenpair by lowest_mode_below against the dense spectrum: on the packing's M shifted down
//     by s (every eigenvalue lambda - s, the zero modes the lowest cluster) the eigenvalue within
//     1e-12 (R) + n eps R, the eigenvector inside the dense zero-mode subspace to 1e-8 (Davis-Kahan: residual
//     1e-12 R over the gap to the first non-zero mode, 1e-4 R). The saddle decision and the move on the
//     closed-form saddles of the saddle tests (verification/dpm/protocols/saddle.cpp) and on the packing.
#include "dpm/analysis/packing_hessian3d.hpp"
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "support/quartic_valley.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::quartic_valley;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// 8 icosahedral shells jammed at P_t = 1e-5 k_v v0 (the protocol's dense path), left at FIRE's end state.
Jam3dResult fire_packing()
{
    Jam3dOptions o;
    o.particles = 8;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-5;
    o.seed = 3;
    return jam3d(o);
}

SparseHessianOf sparse_of(const EnergyWithDerivatives& energy)
{
    return [energy](const Eigen::VectorXd& r) {
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(r.size(), r.size());
        energy(r, nullptr, &h);
        return Eigen::SparseMatrix<double>(h.sparseView());
    };
}

} // namespace

TEST_CASE("3D protocol: sparse largest eigenvalue, polish and saddle test equal the dense ones [DPM sec. "
          "9.4.3, eq. 9.28]")
{
    const Jam3dResult j = fire_packing();
    const DpmSystem3d& s = j.system;
    REQUIRE(j.x.size() <= dense_hessian_limit3d);
    CHECK_FALSE(uses_sparse_hessian(HessianStorage::automatic, j.x.size()));
    CHECK(uses_sparse_hessian(HessianStorage::automatic, dense_hessian_limit3d + 1));

    // (a) FIRE's time step comes from lambda_max.
    const double dense_max = largest_eigenvalue3d(s, j.x, HessianStorage::dense);
    const double sparse_max = largest_eigenvalue3d(s, j.x, HessianStorage::sparse);
    MESSAGE("lambda_max dense " << dense_max << ", sparse " << sparse_max);
    CHECK_CLOSE(sparse_max, dense_max, (Tolerance{1e-10, 0}));

    // (b) The polish from FIRE's end state.
    Eigen::VectorXd dense_x = j.x, sparse_x = j.x;
    const double dense_force = polish_for_modes3d(s, dense_x, j.pressure_unit, HessianStorage::dense);
    const double sparse_force = polish_for_modes3d(s, sparse_x, j.pressure_unit, HessianStorage::sparse);
    const double moved = (sparse_x - dense_x).cwiseAbs().maxCoeff();
    MESSAGE("largest force after the polish: dense "
            << dense_force / j.pressure_unit << ", sparse " << sparse_force / j.pressure_unit
            << " P-units; positions differ by " << moved << " sigma");
    CHECK(dense_force < 1e-14 * j.pressure_unit);
    CHECK(sparse_force < 1e-14 * j.pressure_unit);
    CHECK(moved < 1e-8);

    // (c) The lowest eigenpair: the dense spectrum of the polished packing, the sparse lowest mode of M - s.
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
    total_energy3d(s, dense_x, nullptr, &dense);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(dense);
    const Eigen::VectorXd& lambda = spectrum.eigenvalues();
    const Eigen::SparseMatrix<double> sparse = sparse_dynamical_matrix3d(s, dense_x);
    const double bound = gershgorin_bound(sparse);
    const double threshold = zero_mode_threshold(lambda / j.eigenvalue_unit, 1e-10);
    const Eigen::Index zero = (lambda.array() / j.eigenvalue_unit < threshold).count();
    REQUIRE(zero >= 3); // the uniform translations at least
    REQUIRE(lambda(zero) > 1e-6 * bound);
    CHECK_FALSE(lowest_mode_below(sparse, threshold * j.eigenvalue_unit)); // a minimum: no negative mode
    const double shift = 1e-3 * lambda(zero);
    Eigen::SparseMatrix<double> identity(sparse.rows(), sparse.cols());
    identity.setIdentity();
    const std::optional<LowestModes> lowest = lowest_mode_below(sparse - shift * identity, 0.5 * shift);
    REQUIRE(lowest);
    CHECK_CLOSE(lowest->spectrum.eigenvalues(0), lambda(0) - shift,
                (Tolerance{0, (1e-12 + j.x.size() * round_off) * bound}));
    const Eigen::VectorXd mode = lowest->spectrum.eigenvectors.col(0);
    const Eigen::MatrixXd zero_modes = spectrum.eigenvectors().leftCols(zero);
    const double outside = (mode - zero_modes * (zero_modes.transpose() * mode)).norm();
    MESSAGE(zero << " zero modes; the sparse lowest mode lies outside their span by " << outside);
    CHECK(outside < 1e-8);

    // The saddle decision at this minimum: both leave it alone.
    Eigen::VectorXd dense_kept = dense_x, sparse_kept = dense_x;
    CHECK_FALSE(
        leave_saddle3d(s, dense_kept, j.pressure_unit, j.eigenvalue_unit, 1e-10, 0.1, HessianStorage::dense));
    CHECK_FALSE(leave_saddle3d(s, sparse_kept, j.pressure_unit, j.eigenvalue_unit, 1e-10, 0.1,
                               HessianStorage::sparse));
    CHECK(sparse_kept == dense_x);
}

TEST_CASE("sparse saddle test: the same decision and move as the dense one on closed-form saddles [decision "
          "dpm-packing-minimum]")
{
    struct Case
    {
        std::string name;
        EnergyWithDerivatives energy;
        double threshold;
        bool saddle;
    };
    // A saddle moved to 0.065536 along x (saddle.cpp); a minimum; a negative curvature that lowers U by less
    // than its round-off.
    const Case cases[] = {{"saddle", quartic_valley(0.0, -1.0, 1.0), 1e-10, true},
                          {"minimum", quartic_valley(0.0, 1.0, 0.0), 1e-10, false},
                          {"round-off saddle", quartic_valley(1.0, -1e-12, 1.0), 1e-14, false}};
    for (const Case& c : cases) {
        CAPTURE(c.name);
        Eigen::VectorXd dense_x = Eigen::Vector2d::Zero(), sparse_x = dense_x;
        CHECK(leave_saddle(c.energy, dense_x, 1.0, 1.0, c.threshold, 0.1) == c.saddle);
        CHECK(leave_saddle_sparse(c.energy, sparse_of(c.energy), sparse_x, 1.0, 1.0, c.threshold, 0.1, 1.0) ==
              c.saddle);
        // The same amplitude along the unit mode, whose computed components carry their solver's round-off.
        CHECK_CLOSE(std::abs(sparse_x(0)), std::abs(dense_x(0)), (Tolerance{0, 16 * round_off}));
        CHECK_CLOSE(sparse_x(1), dense_x(1), (Tolerance{0, 16 * round_off}));
    }
}
