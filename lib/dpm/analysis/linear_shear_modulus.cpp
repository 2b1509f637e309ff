#include "dpm/analysis/linear_shear_modulus.hpp"

#include "core/errors.hpp"
#include "dpm/analysis/sparse_modes.hpp"

#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <string>
#include <vector>

namespace softgrain::dpm {

namespace {

// Eigenvalues of h below tau (Sylvester's inertia), NumericalError where the factor breaks down.
int count_below(const Eigen::SparseMatrix<double>& h, double tau)
{
    const int count = eigenvalues_below(h, tau);
    if (count < 0)
        throw NumericalError("LDL^T of the Hessian shifted by " + std::to_string(-tau), 0,
                             "a zero pivot: an eigenvalue at the shift, or a non-finite entry");
    return count;
}

// The coordinates to pin, one per zero mode: the first columns of the column-pivoted QR of N^T, where the
// rows of N are best conditioned (a pinned set on which N is singular would leave a zero mode in the
// reduced matrix).
std::vector<bool> pinned_coordinates(const Eigen::MatrixXd& null_space)
{
    std::vector<bool> pinned(static_cast<std::size_t>(null_space.rows()), false);
    if (null_space.cols() == 0) return pinned;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(null_space.transpose());
    for (Eigen::Index k = 0; k < null_space.cols(); ++k)
        pinned[static_cast<std::size_t>(qr.colsPermutation().indices()(k))] = true;
    return pinned;
}

// Solves h z = b with the pinned coordinates of z zero: the sparse LDL^T of the principal submatrix of h
// on the other coordinates.
Eigen::VectorXd solve_pinned(const Eigen::SparseMatrix<double>& h, const Eigen::VectorXd& b,
                             const std::vector<bool>& pinned)
{
    const Eigen::Index n = h.rows();
    std::vector<int> reduced_index(static_cast<std::size_t>(n), -1);
    int free_count = 0;
    for (Eigen::Index i = 0; i < n; ++i)
        if (!pinned[i]) reduced_index[i] = free_count++;
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index column = 0; column < h.outerSize(); ++column)
        for (Eigen::SparseMatrix<double>::InnerIterator entry(h, column); entry; ++entry)
            if (!pinned[entry.row()] && !pinned[entry.col()])
                entries.emplace_back(reduced_index[entry.row()], reduced_index[entry.col()], entry.value());
    Eigen::SparseMatrix<double> reduced(free_count, free_count);
    reduced.setFromTriplets(entries.begin(), entries.end());
    Eigen::VectorXd reduced_b(free_count);
    for (Eigen::Index i = 0; i < n; ++i)
        if (!pinned[i]) reduced_b(reduced_index[i]) = b(i);
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(reduced);
    if (ldlt.info() != Eigen::Success)
        throw NumericalError("sparse LDL^T of the Hessian with the zero modes pinned", 0,
                             "a zero pivot: a zero mode the inertia count missed");
    const Eigen::VectorXd reduced_z = ldlt.solve(reduced_b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i)
        if (!pinned[i]) z(i) = reduced_z(reduced_index[i]);
    return z;
}

} // namespace

LinearShearModulus linear_shear_modulus(const Eigen::SparseMatrix<double>& h, const StrainDerivatives& strain,
                                        double volume)
{
    LinearShearModulus out;
    out.largest_eigenvalue = largest_eigenvalue(h);
    const double tau = pseudo_inverse_cut * out.largest_eigenvalue;
    out.negative_modes = count_below(h, -tau);
    const int below = count_below(h, tau);
    out.zero_modes = below - out.negative_modes;
    Eigen::MatrixXd null_space(h.rows(), 0);
    if (below > 0) null_space = lowest_modes(h, below).spectrum.eigenvectors.rightCols(out.zero_modes);

    const Eigen::VectorXd& xi = strain.mixed;
    const Eigen::VectorXd along_zero_modes = null_space.transpose() * xi;
    out.zero_mode_load = xi.norm() > 0 ? along_zero_modes.norm() / xi.norm() : 0.0;
    const Eigen::VectorXd b = xi - null_space * along_zero_modes;
    const Eigen::VectorXd z = solve_pinned(h, b, pinned_coordinates(null_space));
    out.residual = b.norm() > 0 ? (h * z - b).norm() / b.norm() : 0.0;

    out.stress = strain.first / volume;
    out.affine = strain.second / volume;
    out.relaxation = b.dot(z) / volume;
    out.modulus = out.affine - out.relaxation;
    return out;
}

namespace {

template <class System, class Assemble>
LinearShearModulus linear_shear_modulus_of(const System& system, const Eigen::VectorXd& x, double volume,
                                           const Assemble& assemble)
{
    StrainDerivatives strain;
    strain.x = &x;
    strain.mixed = Eigen::VectorXd::Zero(x.size());
    const Eigen::SparseMatrix<double> h = assemble(system, x, &strain);
    return linear_shear_modulus(h, strain, volume);
}

} // namespace

LinearShearModulus linear_shear_modulus(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box) throw InputError("linear shear modulus: the system has no periodic box");
    return linear_shear_modulus_of(system, x, system.box->prod(), sparse_dynamical_matrix);
}

LinearShearModulus linear_shear_modulus(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    if (!system.box) throw InputError("linear shear modulus: the system has no periodic box");
    const double side = *system.box;
    return linear_shear_modulus_of(system, x, side * side * side, sparse_dynamical_matrix3d);
}

} // namespace softgrain::dpm
