// The Hessian M of a 3D packing (eq. 9.28) where the jamming protocol (jam3d.hpp) and dpm.modes3d need it:
// FIRE's time step from its largest eigenvalue, the Newton polish to a round-off equilibrium
// (polish_for_modes) and the saddle test (leave_saddle). Up to dense_hessian_limit3d degrees of freedom M is
// a dense matrix and these are modes.hpp's dense functions (Eigen's SelfAdjointEigenSolver); above it M is a
// sparse matrix assembled from the same local terms (sparse_dynamical_matrix3d), its largest eigenvalue comes
// from Lanczos, the polish takes regularised Newton steps on its LDL^T factor and the saddle test shift-and-
// invert Lanczos for the lowest eigenpair alone (sparse_modes.hpp): memory and time grow with the non-zeros,
// not with n^2 and n^3.
#pragma once

#include "dpm/analysis/modes.hpp"
#include "dpm/system/system3d.hpp"

#include <Eigen/SparseCore>
#include <functional>

namespace softgrain::dpm {

enum class HessianStorage {
    automatic, // dense up to dense_hessian_limit3d degrees of freedom, sparse above
    dense,
    sparse
};

// Degrees of freedom up to which the 3D protocol keeps the dense Hessian. The dense path is what every result
// so far was computed with (a time step that differs in the last bit changes FIRE's whole path), and its
// largest run is the paper-scale 16 x 42 packing of DPM-Fig9.15b (n = 2016: 32 MiB per matrix; one
// eigensolve with eigenvectors 12 s, eigenvalues alone 1.2 s on this 2-core machine, and a polish takes up
// to 30 of the former). At 32 x 42 (n = 4032) it is 130 MiB and 20 s per eigenvalue solve, about 100 s with
// eigenvectors, growing as n^3: the 128 x 42 packing of Fig. 9.16b (n = 16 128) needs 2 GiB per matrix and
// hours. Above the limit the sparse path (measured at 32 x 42 in reproductions/dpm/README.md).
constexpr Eigen::Index dense_hessian_limit3d = 2048;
bool uses_sparse_hessian(HessianStorage storage, Eigen::Index degrees_of_freedom);

// The Hessian of an energy at x as a sparse symmetric matrix.
using SparseHessianOf = std::function<Eigen::SparseMatrix<double>(const Eigen::VectorXd&)>;

// polish_newton with sparse steps: Newton steps x -= dx, (M + mu I) dx = grad U with mu = |grad U| / length
// (the regularisation of Li, Fukushima, Qi & Yamashita that keeps the convergence quadratic where M is
// singular), at least pseudo_inverse_cut R (R >= every |lambda|, Gershgorin): the modes the dense
// pseudo-inverse leaves out are damped instead; raised to make M + mu I definite (regularised_newton_step,
// newton_relax.hpp). polish_newton's damping (damped_step_fraction). Ends where the largest force is below
// force_tolerance, after max_steps, or after 3 steps in a row that do not lower the lowest largest force
// reached (at the round-off floor the steps only wander along the near-zero modes, measured on 8 x 42 shells:
// 2e-14 P-units after 2 steps, then 3e-9 after 30 when every step below the start's force was kept); x
// becomes the point of the lowest largest force, which is returned. `length`: the smallest vertex diameter.
double polish_newton_sparse(const EnergyWithDerivatives& energy, const SparseHessianOf& hessian,
                            Eigen::VectorXd& x, double force_tolerance, int max_steps, double length);

// leave_saddle with the sparse path: polish_newton_sparse to polish_for_modes' tolerance, then the saddle
// test lambda_0 <= -zero_mode_threshold(n, lambda_max, threshold) (lambda_max by Lanczos) by
// lowest_mode_below, and the move along that mode (step_off_saddle).
bool leave_saddle_sparse(const EnergyWithDerivatives& energy, const SparseHessianOf& hessian,
                         Eigen::VectorXd& x, double force_unit, double eigenvalue_unit, double threshold,
                         double max_amplitude, double length);

// The total energy of a 3D system as an EnergyWithDerivatives and its sparse Hessian; `system` must outlive
// them.
EnergyWithDerivatives system_energy3d(const DpmSystem3d& system);
SparseHessianOf system_sparse_hessian3d(const DpmSystem3d& system);

// polish_newton on the total energy of a 3D system, dense or sparse by `storage` (polish_newton_sparse):
// Newton to a largest force below force_tolerance, at most max_steps; returns the largest force reached.
double polish_newton3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_tolerance, int max_steps,
                       HessianStorage storage);

// The three uses of the 3D protocol, dense or sparse by `storage`: the largest eigenvalue of M [k_c],
// polish_for_modes and leave_saddle.
double largest_eigenvalue3d(const DpmSystem3d& system, const Eigen::VectorXd& x, HessianStorage storage);
double polish_for_modes3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_unit,
                          HessianStorage storage);
bool leave_saddle3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_unit, double eigenvalue_unit,
                    double threshold, double max_amplitude, HessianStorage storage);

} // namespace softgrain::dpm
