// The lowest vibrational modes of a large packing (DPM sec. 9.4.3: the soft, quartic and zero modes). The
// dynamical matrix M of eq. (9.28) is assembled as a sparse matrix from the same local terms as the dense one
// (HessianSink triplets, local_derivatives.hpp), and its `count` lowest eigenpairs come from shift-and-invert
// Lanczos (Spectra's SymEigsShiftSolver): the largest eigenvalues 1/(lambda - sigma) of (M - sigma)^{-1},
// applied by a sparse LDL^T factor (Eigen's SimplicialLDLT). Memory and time grow with the non-zeros of the
// factor instead of n^2 and n^3: the dense spectrum of a 128 x 42 3D packing (n = 16 128) needs 2 GB for M
// and as much again for its eigenvectors.
#pragma once

#include "dpm/analysis/modes.hpp"

#include <Eigen/SparseCore>
#include <optional>

namespace softgrain::dpm {

// Eq. (9.28) as a sparse matrix: the same local terms as dynamical_matrix, summed by setFromTriplets. With
// `strain` (its x pointing at x, its `mixed` zero and of the size of x), the derivatives with respect to
// the Lees-Edwards strain are added from the same terms (local_derivatives.hpp).
Eigen::SparseMatrix<double> sparse_dynamical_matrix(const DpmSystem& system, const Eigen::VectorXd& x,
                                                    StrainDerivatives* strain = nullptr);
Eigen::SparseMatrix<double> sparse_dynamical_matrix3d(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                                      StrainDerivatives* strain = nullptr);

struct LowestModes
{
    ModeSpectrum spectrum; // the `count` lowest eigenvalues (ascending) and unit eigenvectors
    double largest_eigenvalue =
        0;                  // lambda_max of M (plain Lanczos), for the round-off bound n eps max|lambda|
    double shift = 0;       // sigma: M - sigma is positive definite (every LDL^T pivot positive)
    int factorizations = 0; // shifts tried until the factor was definite
    int restarts = 0;       // of the shift-and-invert Lanczos iteration
    int solves = 0;         // applications of (M - sigma)^{-1}
    int passes = 0;         // Lanczos passes: 1, plus one per deflated search for modes a pass missed
    double completeness_bound = 0; // tau of the last pass that found the count incomplete (0: none did)
};

// max_i sum_j |m_ij|: a bound on every |lambda| of the symmetric sparse m (Gershgorin).
double gershgorin_bound(const Eigen::SparseMatrix<double>& m);

// Number of eigenvalues of the symmetric sparse m below tau: the negative pivots of the LDL^T of m - tau
// (Sylvester's law of inertia); -1 where the factor breaks down (a zero pivot).
int eigenvalues_below(const Eigen::SparseMatrix<double>& m, double tau);

// lambda_max of the symmetric sparse m by plain Lanczos (a few products: it lies at the end of the
// spectrum); Spectra's relative tolerance 1e-12, a Krylov space of `lanczos_vectors` (at most rows). Where
// that does not converge in 1000 restarts, again with 4 times as many; then NumericalError. A packing's top
// eigenvalues form a band (every particle's stiffest local modes, alike): on 64 x 42 shells (n = 8064) 20
// vectors did not converge, 80 did in 24 restarts (3 s).
double largest_eigenvalue(const Eigen::SparseMatrix<double>& m, Eigen::Index lanczos_vectors = 20);

// The `count` lowest eigenpairs of the symmetric sparse m (1 <= count < rows). The shift starts at
// sigma = -1e-6 R, R = max_i sum_j |m_ij| (Gershgorin: every |lambda| <= R), below the zero modes and the
// slightly negative modes of a saddle; where the LDL^T factor of m - sigma has a pivot <= 0 (Sylvester's
// inertia: an eigenvalue at or below sigma) sigma is multiplied by 10, at most to -2 R (always definite). A
// definite shift keeps the factor without pivoting stable (the LDL^T of a positive definite matrix is
// backward stable) and every 1/(lambda - sigma) positive, so the largest of them are the lowest lambda.
// The condition number of m - sigma, at most (1 + 1e6) for the first shift, costs at most 1e6 eps in the
// solves, along the near-null directions the iteration seeks. Convergence: Spectra's relative residual
// 1e-12 on 1/(lambda - sigma), i.e. lambda to 1e-12 (lambda - sigma) or better; the Krylov space holds
// max(2 count + 1, count + 40) vectors (at most rows). Completeness: the inertia of M - tau, tau 1e-9 R above
// the highest found, counts the eigenvalues below it; single-vector Lanczos can miss copies of a degenerate
// eigenvalue, and those are sought by further passes on (M - sigma)^{-1} with the modes found deflated
// (projected out). NumericalError with the converged count, the shift and the restarts when the iteration
// does not converge in 1000 restarts, or when a deflated pass finds no missing mode.
LowestModes lowest_modes(const Eigen::SparseMatrix<double>& m, int count);

// The lowest eigenpair of the symmetric sparse m if its eigenvalue lies at or below -threshold (threshold
// > 0), nothing otherwise: the test for a saddle without the whole spectrum (leave_saddle3d). Nothing when
// m + threshold I factors with every LDL^T pivot positive (Sylvester's law of inertia: no eigenvalue at or
// below -threshold). Otherwise the shift sigma = -10^k threshold, k = 1, 2, ..., stops at the first at
// which m - sigma is definite (at most -2 R, R the Gershgorin bound), so that lambda_0 lies in (sigma,
// sigma/10] and 1/(lambda_0 - sigma) stands at least 10/9 above 1/(lambda - sigma) of every eigenvalue
// lambda >= 0 (the zero modes included, however degenerate): shift-and-invert Lanczos (Spectra, relative
// tolerance 1e-12 as in lowest_modes) then separates it in a few restarts. NumericalError as lowest_modes.
std::optional<LowestModes> lowest_mode_below(const Eigen::SparseMatrix<double>& m, double threshold);

} // namespace softgrain::dpm
