#include "dpm/sparse_modes.hpp"

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

// y = (m - sigma)^{-1} x by a sparse LDL^T factor, the operator Spectra's shift-and-invert solver iterates.
// The factor is computed once, for the shift the caller has checked to be definite (factor_definite).
class ShiftedInverse
{
  public:
    using Scalar = double;

    explicit ShiftedInverse(const Eigen::SparseMatrix<double>& m) : m_(m) {}
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
    void set_shift(double sigma) const
    {
        if (sigma != shift_)
            throw std::logic_error("ShiftedInverse: the shift differs from the factored one");
    }
    void perform_op(const double* x_in, double* y_out) const
    {
        Eigen::Map<Eigen::VectorXd>(y_out, rows()) =
            ldlt_.solve(Eigen::Map<const Eigen::VectorXd>(x_in, rows()));
    }

  private:
    const Eigen::SparseMatrix<double>& m_;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
    double shift_ = 0;
};

// max_i sum_j |m_ij|: a bound on every |lambda| (Gershgorin), the scale of the first shift.
double gershgorin_bound(const Eigen::SparseMatrix<double>& m)
{
    Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(m.rows());
    for (Eigen::Index column = 0; column < m.outerSize(); ++column)
        for (Eigen::SparseMatrix<double>::InnerIterator entry(m, column); entry; ++entry)
            row_sums(entry.row()) += std::abs(entry.value());
    return row_sums.maxCoeff();
}

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

int eigenvalues_below(const Eigen::SparseMatrix<double>& m, double tau)
{
    Eigen::SparseMatrix<double> identity(m.rows(), m.cols());
    identity.setIdentity();
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m - tau * identity);
    if (ldlt.info() != Eigen::Success) return -1;
    return static_cast<int>((ldlt.vectorD().array() < 0).count());
}

double largest_eigenvalue(const Eigen::SparseMatrix<double>& m)
{
    Spectra::SparseSymMatProd<double> product(m);
    const Eigen::Index ncv = std::min<Eigen::Index>(m.rows(), 20);
    Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> solver(product, 1, ncv);
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12);
    if (solver.info() != Spectra::CompInfo::Successful)
        throw NumericalError("largest eigenvalue of the sparse dynamical matrix (Lanczos, " +
                                 std::to_string(m.rows()) + " rows)",
                             solver.num_iterations(), "no convergence in 1000 restarts: a non-finite entry");
    return solver.eigenvalues()(0);
}

LowestModes lowest_modes(const Eigen::SparseMatrix<double>& m, int count)
{
    const Eigen::Index n = m.rows();
    if (count < 1 || count >= n)
        throw std::logic_error("lowest_modes: count " + std::to_string(count) + " outside 1 ... " +
                               std::to_string(n - 1));
    LowestModes out;
    const double bound = gershgorin_bound(m);
    ShiftedInverse inverse(m);
    out.shift = -1e-6 * bound;
    for (out.factorizations = 1; !inverse.factor_definite(out.shift); ++out.factorizations) {
        if (out.shift <= -bound)
            throw NumericalError("LDL^T factor of M - sigma at sigma = " + std::to_string(out.shift) +
                                     " = -max row sum of |M|",
                                 out.factorizations,
                                 "a pivot <= 0 where M - sigma is definite by Gershgorin: a non-finite entry "
                                 "of M or a factor ruined by round-off");
        out.shift = std::max(10 * out.shift, -bound);
    }
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max(2 * count + 1, count + 40));
    Spectra::SymEigsShiftSolver<ShiftedInverse> solver(inverse, count, ncv, out.shift);
    solver.init();
    const Eigen::Index converged =
        solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
    out.restarts = static_cast<int>(solver.num_iterations());
    out.solves = static_cast<int>(solver.num_operations());
    if (solver.info() != Spectra::CompInfo::Successful)
        throw NumericalError("shift-and-invert Lanczos for the " + std::to_string(count) + " lowest modes (" +
                                 std::to_string(converged) + " converged, shift " +
                                 std::to_string(out.shift) + ", " + std::to_string(ncv) + " Lanczos vectors)",
                             out.restarts,
                             "eigenvalues 1/(lambda - sigma) too close together to separate in 1000 restarts "
                             "(a cluster of modes straddling the count-th); ask for more or fewer modes");
    out.spectrum = {solver.eigenvalues(), solver.eigenvectors()};
    // Completeness: Lanczos from one start vector can miss copies of a degenerate eigenvalue (a symmetric
    // packing) and return higher ones instead; then more than `count` eigenvalues lie below the highest found.
    const double tau = out.spectrum.eigenvalues(count - 1) + 1e-9 * bound;
    const int below = eigenvalues_below(m, tau);
    if (below != count)
        throw NumericalError(
            "completeness of the " + std::to_string(count) + " lowest modes: " + std::to_string(below) +
                " eigenvalues lie below " + std::to_string(tau) +
                " (inertia of the LDL^T of M - tau; -1: the factor broke down)",
            out.restarts,
            "a degenerate cluster of modes that single-vector Lanczos resolves only in part, or "
            "a cluster cut by the count; ask for fewer modes, below the cluster");
    out.largest_eigenvalue = largest_eigenvalue(m);
    return out;
}

} // namespace softgrain::dpm
