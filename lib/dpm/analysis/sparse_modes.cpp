#include "dpm/analysis/sparse_modes.hpp"

#include "core/errors.hpp"

#include <Eigen/SparseCholesky>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymEigsShiftSolver.h>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace softgrain::dpm {

namespace {

Eigen::SparseMatrix<double> from_triplets(const std::vector<Eigen::Triplet<double>>& triplets, Eigen::Index n)
{
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(triplets.begin(), triplets.end()); // sums the terms of each entry
    return m;
}

// y = P (m - sigma)^{-1} P x by a sparse LDL^T factor, the operator Spectra's shift-and-invert solver
// iterates; P = 1 - Q Q^T projects out the modes already found (the columns of Q, orthonormal), so that
// their eigenvalues 1/(lambda - sigma) become 0 and the iteration finds the next ones (deflation). Without Q,
// P = 1. The factor is computed once, for the shift the caller has checked to be definite (factor_definite).
class ShiftedInverse
{
  public:
    using Scalar = double;

    explicit ShiftedInverse(const Eigen::SparseMatrix<double>& m) : m_(m), deflation_(m.rows(), 0) {}
    Eigen::Index rows() const { return m_.rows(); }
    Eigen::Index cols() const { return m_.cols(); }

    // True when m - sigma factors with every pivot positive, i.e. is positive definite (Sylvester's law of
    // inertia: the pivots have the signs of its eigenvalues).
    bool factor_definite(double sigma)
    {
        Eigen::SparseMatrix<double> identity(rows(), cols());
        identity.setIdentity();
        ldlt_.compute(m_ - sigma * identity);
        shift_ = sigma;
        return ldlt_.info() == Eigen::Success && ldlt_.vectorD().minCoeff() > 0;
    }
    void deflate(const Eigen::MatrixXd& found_modes) { deflation_ = found_modes; }
    void set_shift(double sigma) const
    {
        if (sigma != shift_)
            throw std::logic_error("ShiftedInverse: the shift differs from the factored one");
    }
    void perform_op(const double* x_in, double* y_out) const
    {
        Eigen::Map<Eigen::VectorXd> y(y_out, rows());
        y = ldlt_.solve(without_found_modes(Eigen::Map<const Eigen::VectorXd>(x_in, rows())));
        y = without_found_modes(y);
    }

  private:
    Eigen::VectorXd without_found_modes(const Eigen::VectorXd& v) const
    {
        return v - deflation_ * (deflation_.transpose() * v);
    }

    const Eigen::SparseMatrix<double>& m_;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
    Eigen::MatrixXd deflation_; // Q
    double shift_ = 0;
};

} // namespace

Eigen::SparseMatrix<double> sparse_dynamical_matrix(const DpmSystem& system, const Eigen::VectorXd& x,
                                                    StrainDerivatives* strain)
{
    std::vector<Eigen::Triplet<double>> triplets;
    total_energy(system, x, nullptr, HessianSink(&triplets, strain));
    return from_triplets(triplets, x.size());
}

Eigen::SparseMatrix<double> sparse_dynamical_matrix3d(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                                      StrainDerivatives* strain)
{
    std::vector<Eigen::Triplet<double>> triplets;
    total_energy3d(system, x, nullptr, HessianSink(&triplets, strain));
    return from_triplets(triplets, x.size());
}

double gershgorin_bound(const Eigen::SparseMatrix<double>& m)
{
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(m.rows());
    for (Eigen::Index column = 0; column < m.outerSize(); ++column)
        for (Eigen::SparseMatrix<double>::InnerIterator entry(m, column); entry; ++entry)
            row_sums(entry.row()) += std::abs(entry.value());
    return row_sums.maxCoeff();
}

int eigenvalues_below(const Eigen::SparseMatrix<double>& m, double tau)
{
    Eigen::SparseMatrix<double> identity(m.rows(), m.cols());
    identity.setIdentity();
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m - tau * identity);
    if (ldlt.info() != Eigen::Success) return -1;
    return static_cast<int>((ldlt.vectorD().array() < 0).count());
}

double largest_eigenvalue(const Eigen::SparseMatrix<double>& m, Eigen::Index lanczos_vectors)
{
    Spectra::SparseSymMatProd<double> product(m);
    int restarts = 0;
    for (const Eigen::Index wanted : {lanczos_vectors, 4 * lanczos_vectors}) {
        const Eigen::Index ncv = std::min<Eigen::Index>(m.rows(), wanted);
        Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> solver(product, 1, ncv);
        solver.init();
        solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12);
        restarts += static_cast<int>(solver.num_iterations());
        if (solver.info() == Spectra::CompInfo::Successful) return solver.eigenvalues()(0);
    }
    throw NumericalError("largest eigenvalue of the sparse dynamical matrix (Lanczos, " +
                             std::to_string(m.rows()) + " rows, " + std::to_string(4 * lanczos_vectors) +
                             " Lanczos vectors)",
                         restarts, "no convergence in 1000 restarts: a non-finite entry");
}

namespace {

// The `count` largest eigenvalues 1/(lambda - sigma) of the (deflated) shifted inverse as eigenpairs of m,
// ascending; NumericalError when Lanczos does not converge in 1000 restarts.
ModeSpectrum lanczos_pass(ShiftedInverse& inverse, int count, LowestModes& out)
{
    const Eigen::Index ncv = std::min<Eigen::Index>(inverse.rows(), std::max(2 * count + 1, count + 40));
    Spectra::SymEigsShiftSolver<ShiftedInverse> solver(inverse, count, ncv, out.shift);
    solver.init();
    const Eigen::Index converged =
        solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
    out.restarts += static_cast<int>(solver.num_iterations());
    out.solves += static_cast<int>(solver.num_operations());
    if (solver.info() != Spectra::CompInfo::Successful)
        throw NumericalError("shift-and-invert Lanczos for " + std::to_string(count) + " modes (" +
                                 std::to_string(converged) + " converged, shift " +
                                 std::to_string(out.shift) + ", " + std::to_string(ncv) + " Lanczos vectors)",
                             out.restarts,
                             "eigenvalues 1/(lambda - sigma) too close together to separate in 1000 restarts "
                             "(a cluster of modes straddling the count-th); ask for more or fewer modes");
    return {solver.eigenvalues(), solver.eigenvectors()};
}

// Factors m - sigma for sigma = first, 10 first, 100 first, ... until every pivot is positive; out.shift
// becomes that sigma, out.factorizations the factors computed. At most -2 R (R the Gershgorin bound, every
// lambda >= -R, so that m + 2 R is definite; m + R is singular where lambda_0 = -R).
void factor_definite_shift(ShiftedInverse& inverse, double first, double bound, LowestModes& out)
{
    out.shift = first;
    for (out.factorizations = 1; !inverse.factor_definite(out.shift); ++out.factorizations) {
        if (out.shift <= -2 * bound)
            throw NumericalError("LDL^T factor of M - sigma at sigma = " + std::to_string(out.shift) +
                                     " = -2 max row sum of |M|",
                                 out.factorizations,
                                 "a pivot <= 0 where M - sigma is definite by Gershgorin: a non-finite entry "
                                 "of M or a factor ruined by round-off");
        out.shift = std::max(10 * out.shift, -2 * bound);
    }
}

// The union of two sets of eigenpairs, ascending.
ModeSpectrum merged(const ModeSpectrum& first, const ModeSpectrum& second)
{
    const Eigen::Index total = first.eigenvalues.size() + second.eigenvalues.size();
    Eigen::VectorXd values(total);
    values << first.eigenvalues, second.eigenvalues;
    Eigen::MatrixXd vectors(first.eigenvectors.rows(), total);
    vectors << first.eigenvectors, second.eigenvectors;
    std::vector<Eigen::Index> order(static_cast<std::size_t>(total));
    for (Eigen::Index k = 0; k < total; ++k)
        order[static_cast<std::size_t>(k)] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](Eigen::Index a, Eigen::Index b) { return values(a) < values(b); });
    ModeSpectrum out{Eigen::VectorXd(total), Eigen::MatrixXd(vectors.rows(), total)};
    for (Eigen::Index k = 0; k < total; ++k) {
        out.eigenvalues(k) = values(order[static_cast<std::size_t>(k)]);
        out.eigenvectors.col(k) = vectors.col(order[static_cast<std::size_t>(k)]);
    }
    return out;
}

} // namespace

LowestModes lowest_modes(const Eigen::SparseMatrix<double>& m, int count)
{
    const Eigen::Index n = m.rows();
    if (count < 1 || count >= n)
        throw std::logic_error("lowest_modes: count " + std::to_string(count) + " outside 1 ... " +
                               std::to_string(n - 1));
    LowestModes out;
    const double bound = gershgorin_bound(m);
    ShiftedInverse inverse(m);
    factor_definite_shift(inverse, -1e-6 * bound, bound, out);
    // Completeness: Lanczos from one start vector can miss copies of a degenerate eigenvalue (the zero modes,
    // a symmetric packing) and return higher ones instead; then more than `count` eigenvalues lie below the
    // count-th found (Sylvester's inertia of M - tau, tau 1e-9 R above it). The missing ones are sought
    // again with every mode found so far deflated, until the count agrees. Each pass finds at least one
    // new mode below tau (the lowest of the complement, which the deflated operator holds as its largest
    // 1/(lambda - sigma)), so the passes end; a pass that finds none is reported.
    ModeSpectrum found = lanczos_pass(inverse, count, out);
    for (out.passes = 1;; ++out.passes) {
        const double tau = found.eigenvalues(count - 1) + 1e-9 * bound;
        const int below = eigenvalues_below(m, tau);
        if (below == count) break;
        const int missing = below - count;
        const bool no_progress = out.passes > 1 && tau >= out.completeness_bound;
        out.completeness_bound = tau;
        if (below < 0 || missing < 0 || no_progress || found.eigenvalues.size() + missing >= n)
            throw NumericalError(
                "completeness of the " + std::to_string(count) + " lowest modes: " + std::to_string(below) +
                    " eigenvalues lie below " + std::to_string(tau) + " after " + std::to_string(out.passes) +
                    " deflated Lanczos passes (inertia of the LDL^T of M - tau; -1: the factor broke down)",
                out.restarts,
                "a deflated pass found no new mode below the count-th: eigenvectors of a cluster too close "
                "to "
                "separate; ask for fewer modes, below the cluster");
        inverse.deflate(found.eigenvectors);
        found = merged(found, lanczos_pass(inverse, missing, out));
    }
    out.spectrum = {found.eigenvalues.head(count), found.eigenvectors.leftCols(count)};
    out.largest_eigenvalue = largest_eigenvalue(m);
    return out;
}

std::optional<LowestModes> lowest_mode_below(const Eigen::SparseMatrix<double>& m, double threshold)
{
    ShiftedInverse inverse(m);
    if (inverse.factor_definite(-threshold)) return std::nullopt;
    const double bound = gershgorin_bound(m);
    LowestModes out;
    factor_definite_shift(inverse, std::max(-10 * threshold, -2 * bound), bound, out);
    ++out.factorizations; // the indefinite factor at -threshold
    out.spectrum = lanczos_pass(inverse, 1, out);
    out.passes = 1;
    return out;
}

} // namespace softgrain::dpm
