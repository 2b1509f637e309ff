// Exact first and second derivatives of a local energy term by forward-mode automatic differentiation
// (Eigen's AutoDiffScalar, nested once for the Hessian).
//
// A local term is a function of the coordinates of K points in Dim dimensions, written once as a generic
// callable `term(x)` where x is an Eigen::Matrix<Scalar, K * Dim, 1> (point k occupies rows
// Dim k ... Dim k + Dim - 1) and the result is a Scalar. The same code is then evaluated with
//   double                                    -> the value,
//   AutoDiffScalar<Matrix<double, N, 1>>       -> value and gradient (N = K Dim),
//   AutoDiffScalar<Matrix<that, N, 1>>         -> value, gradient and Hessian.
// Every DPM energy (2D and 3D shape terms, rough and smooth contacts) is such a term, so no Hessian is
// written by hand. The shape terms' local measures also have analytic gradients ("slopes", generic in the
// scalar: shape_energy.hpp, shape_energy3d.hpp), the forces of FIRE, whose first-order AutoDiff Jacobian
// is their Hessian (local_hessian_from_slope) at a fraction of the nested sweep's cost; both are checked
// against the nested sweep. The sizes are fixed at compile time: no allocation.
//
// Rule for writing a term (Eigen's AutoDiff builds expression templates that may refer to temporaries):
// declare the return type as the Scalar and every intermediate as a Scalar, never `auto`. The functions
// below refuse at compile time a term whose result is not exactly the Scalar.
#pragma once

#include <type_traits>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstddef>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

namespace softgrain::dpm {

// Derivatives of U(x, gamma) with respect to the Lees-Edwards strain gamma at fixed coordinates x, in the
// image-shift convention: x holds the unwrapped vertices and gamma enters only through the translations of
// the periodic images, -n_y (gamma L_y, L_y, 0) - ... for an image n_y boxes away in y (contact_list.hpp,
// interactions3d.cpp). A term whose point k is imaged by s_k therefore sees d(x_k + s_k)/dgamma =
// s_{k,y} e_x (and d^2/dgamma^2 = 0), so from its local gradient g and Hessian h, with v_k = s_{k,y} e_x:
//   dU/dgamma += g . v,   d^2U/dgamma^2 += v^T h v,   Xi_k = d^2U/(dx_k dgamma) += (h v)_k.
// Shape terms (one unwrapped particle, s = 0) do not depend on gamma in this convention.
// `x` points at the coordinates the terms are evaluated at: s_k is recovered as local x_k - x_k.
struct StrainDerivatives
{
    const Eigen::VectorXd* x = nullptr;
    Eigen::VectorXd mixed; // Xi = d^2U/dx dgamma [E/L], the size of x, zero to start
    double first = 0;      // dU/dgamma [E]
    double second = 0;     // d^2U/dgamma^2 [E]
};

// Where second derivatives are summed: a dense matrix (the full spectrum of a small system) or a list of
// (row, column, value) triplets that Eigen::SparseMatrix::setFromTriplets sums into the sparse Hessian (the
// lowest modes of a large one, sparse_modes.hpp); a dense n x n Hessian of n = 16 128 degrees of freedom
// needs 2 GB, the triplets grow as n (a few hundred per coordinate). Converts implicitly from a dense matrix pointer and from nullptr (no
// Hessian), so an energy function takes a HessianSink where it took an Eigen::MatrixXd*, and tests it as one.
class HessianSink
{
  public:
    HessianSink(std::nullptr_t = nullptr) {}
    HessianSink(Eigen::MatrixXd* dense) : dense_(dense) {}
    // A dense block whose entry (0, 0) is the Hessian's entry (offset, offset), with the strain derivatives
    // of the same terms (with_dense_block below).
    HessianSink(Eigen::MatrixXd* block, Eigen::Index offset, StrainDerivatives* strain)
        : dense_(block), strain_(strain), offset_(offset)
    {
    }
    HessianSink(std::vector<Eigen::Triplet<double>>* triplets) : triplets_(triplets) {}
    // Triplets (may be null) and the strain derivatives of the same terms.
    HessianSink(std::vector<Eigen::Triplet<double>>* triplets, StrainDerivatives* strain)
        : triplets_(triplets), strain_(strain)
    {
    }
    explicit operator bool() const { return dense_ != nullptr || triplets_ != nullptr || strain_ != nullptr; }
    StrainDerivatives* strain() const { return strain_; }
    bool sparse() const { return triplets_ != nullptr; }

    // Adds `block` to the rows from `row` and the columns from `column`.
    template <class Block>
    void add(Eigen::Index row, Eigen::Index column, const Eigen::MatrixBase<Block>& block)
    {
        if (dense_) {
            dense_->block(row - offset_, column - offset_, block.rows(), block.cols()) += block;
            return;
        }
        if (!triplets_) return; // strain derivatives only
        // Evaluated once: a product expression (the rank-one shape blocks) would be re-evaluated per entry.
        const typename Block::PlainObject values = block;
        for (Eigen::Index j = 0; j < values.cols(); ++j)
            for (Eigen::Index i = 0; i < values.rows(); ++i)
                triplets_->emplace_back(static_cast<int>(row + i), static_cast<int>(column + j),
                                        values(i, j));
    }

  private:
    Eigen::MatrixXd* dense_ = nullptr;
    std::vector<Eigen::Triplet<double>>* triplets_ = nullptr;
    StrainDerivatives* strain_ = nullptr;
    Eigen::Index offset_ = 0;
};

// Runs terms(sink), energy terms that couple only the `count` coordinates from `first` (one particle's shape
// energy), and returns its result. Into a sparse sink their Hessian goes as one dense block, each entry once,
// instead of once per term: a 42-vertex shell's 80 faces, 120 hinges and volume would send 39 636 triplets
// for its 15 876 entries, and the triplets' memory traffic was a third of a 3D Hessian's assembly.
template <class Terms>
double with_dense_block(HessianSink hessian, Eigen::Index first, Eigen::Index count, const Terms& terms)
{
    if (!hessian.sparse()) return terms(hessian);
    Eigen::MatrixXd block = Eigen::MatrixXd::Zero(count, count);
    const double energy = terms(HessianSink(&block, first, hessian.strain()));
    hessian.add(first, first, block);
    return energy;
}

template <int N>
using FirstOrder = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
template <int N>
using SecondOrder = Eigen::AutoDiffScalar<Eigen::Matrix<FirstOrder<N>, N, 1>>;

template <int N>
struct LocalDerivatives
{
    double value = 0;
    Eigen::Matrix<double, N, 1> gradient = Eigen::Matrix<double, N, 1>::Zero();
    Eigen::Matrix<double, N, N> hessian = Eigen::Matrix<double, N, N>::Zero();
};

// Value and gradient of term at x.
template <int N, class Term>
LocalDerivatives<N> local_gradient(const Term& term, const Eigen::Matrix<double, N, 1>& x)
{
    Eigen::Matrix<FirstOrder<N>, N, 1> ad;
    for (int k = 0; k < N; ++k)
        ad(k) = FirstOrder<N>(x(k), N, k);
    static_assert(std::is_same_v<decltype(term(ad)), FirstOrder<N>>, "a term must return its Scalar");
    const FirstOrder<N> result = term(ad);
    LocalDerivatives<N> d;
    d.value = result.value();
    d.gradient = result.derivatives();
    return d;
}

// Value, gradient and Hessian of term at x.
template <int N, class Term>
LocalDerivatives<N> local_hessian(const Term& term, const Eigen::Matrix<double, N, 1>& x)
{
    using Inner = FirstOrder<N>;
    using Outer = SecondOrder<N>;
    Eigen::Matrix<Outer, N, 1> ad;
    for (int k = 0; k < N; ++k) {
        typename Outer::DerType outer_derivatives;
        for (int m = 0; m < N; ++m)
            outer_derivatives(m) = Inner(m == k ? 1.0 : 0.0, Eigen::Matrix<double, N, 1>::Zero());
        ad(k) = Outer(Inner(x(k), N, k), outer_derivatives);
    }
    static_assert(std::is_same_v<decltype(term(ad)), Outer>, "a term must return its Scalar");
    const Outer result = term(ad);
    LocalDerivatives<N> d;
    d.value = result.value().value();
    d.gradient = result.value().derivatives();
    for (int k = 0; k < N; ++k)
        d.hessian.row(k) = result.derivatives()(k).derivatives().transpose();
    return d;
}

// Value, gradient and Hessian of a local measure from its analytic gradient `slope`, a generic callable
// (x, q) -> dq/dx written for any scalar, q the measure's value at x (shape_energy.hpp): the Hessian is the forward-mode Jacobian of the
// gradient, one first-order AutoDiff sweep over the gradient's code instead of local_hessian's nested sweep
// over the measure's (whose scalars carry N (N + 1) numbers). The same exact derivative, to round-off; for
// the dihedral angle (N = 12) about fifteen times cheaper. The Jacobian of a gradient is symmetric, its
// round-off is not: symmetrised, so that the assembled Hessian is symmetric to the last bit.
template <int N, class Measure, class Slope>
LocalDerivatives<N> local_hessian_from_slope(const Measure& measure, const Slope& slope,
                                             const Eigen::Matrix<double, N, 1>& x)
{
    Eigen::Matrix<FirstOrder<N>, N, 1> ad;
    for (int k = 0; k < N; ++k)
        ad(k) = FirstOrder<N>(x(k), N, k);
    const FirstOrder<N> q = measure(ad);
    const Eigen::Matrix<FirstOrder<N>, N, 1> gradient = slope(ad, q);
    LocalDerivatives<N> d;
    d.value = measure(x);
    for (int k = 0; k < N; ++k) {
        d.gradient(k) = gradient(k).value();
        d.hessian.row(k) = gradient(k).derivatives().transpose();
    }
    d.hessian = (0.5 * (d.hessian + d.hessian.transpose())).eval();
    return d;
}

// The value only (double evaluation of the same code).
template <int N, class Term>
double local_value(const Term& term, const Eigen::Matrix<double, N, 1>& x)
{
    static_assert(std::is_same_v<decltype(term(x)), double>, "a term must return its Scalar");
    return term(x);
}

// The coordinates of K points of a flat array (point p at rows Dim p ... Dim p + Dim - 1), in the order of
// `points`, as one local vector.
template <int Dim, int K>
Eigen::Matrix<double, K * Dim, 1> gather(const Eigen::VectorXd& x, const std::array<int, K>& points)
{
    Eigen::Matrix<double, K * Dim, 1> local;
    for (int k = 0; k < K; ++k)
        local.template segment<Dim>(Dim * k) = x.template segment<Dim>(Dim * points[k]);
    return local;
}

// Adds weight * a local gradient (point k at rows Dim k ...) into the global gradient.
template <int Dim, int K>
void scatter_gradient(const Eigen::Matrix<double, K * Dim, 1>& local, const std::array<int, K>& points,
                      double weight, Eigen::VectorXd& gradient)
{
    for (int a = 0; a < K; ++a)
        gradient.template segment<Dim>(Dim * points[a]) += weight * local.template segment<Dim>(Dim * a);
}

// Adds weight * (gradient, Hessian) of a local result into the global arrays (either may be null).
template <int Dim, int K>
void scatter(const LocalDerivatives<K * Dim>& d, const std::array<int, K>& points, double weight,
             Eigen::VectorXd* gradient, HessianSink hessian)
{
    if (gradient) scatter_gradient<Dim, K>(d.gradient, points, weight, *gradient);
    if (!hessian) return;
    for (int a = 0; a < K; ++a) {
        for (int b = 0; b < K; ++b)
            hessian.add(Dim * points[a], Dim * points[b],
                        weight * d.hessian.template block<Dim, Dim>(Dim * a, Dim * b));
    }
}

// Adds the strain derivatives of one local term (StrainDerivatives above) evaluated at local_x.
template <int Dim, int K>
void add_strain_derivatives(const LocalDerivatives<K * Dim>& d, const std::array<int, K>& points,
                            const Eigen::Matrix<double, K * Dim, 1>& local_x, StrainDerivatives& strain)
{
    Eigen::Matrix<double, K * Dim, 1> velocity =
        Eigen::Matrix<double, K * Dim, 1>::Zero(); // d local_x / dgamma
    for (int k = 0; k < K; ++k)
        velocity(Dim * k) = local_x(Dim * k + 1) - (*strain.x)(Dim * points[k] + 1); // s_{k,y}
    if (velocity.isZero(0)) return; // no image: independent of gamma
    const Eigen::Matrix<double, K * Dim, 1> coupling = d.hessian * velocity;
    strain.first += d.gradient.dot(velocity);
    strain.second += velocity.dot(coupling);
    for (int k = 0; k < K; ++k)
        strain.mixed.template segment<Dim>(Dim * points[k]) += coupling.template segment<Dim>(Dim * k);
}

// Adds the derivatives d of one local term over `points`, evaluated at local_x (which may hold periodic
// images), into the global arrays: the gradient, the Hessian and the strain derivatives it asks for.
template <int Dim, int K>
void add_local_derivatives(const LocalDerivatives<K * Dim>& d, const std::array<int, K>& points,
                           const Eigen::Matrix<double, K * Dim, 1>& local_x, Eigen::VectorXd* gradient,
                           HessianSink hessian)
{
    if (hessian.strain()) add_strain_derivatives<Dim, K>(d, points, local_x, *hessian.strain());
    scatter<Dim, K>(d, points, 1.0, gradient, hessian);
}

// Energy of one local term over `points` at local coordinates `local_x` (which may hold periodic images),
// adding its gradient and Hessian (when asked for) into the global arrays. Returns the energy.
// `virial`, when given, accumulates sum_k y_k F_k^T (W_ab = sum_k y_{k,a} F_{k,b}, F = -grad) over the
// term's points at their local coordinates y_k: the force moment of eqs. (9.25)-(9.26). A term that is
// invariant under translation has sum_k F_k = 0, so the moment does not depend on which image is used.
template <int Dim, int K, class Term>
double add_local_term(const Term& term, const std::array<int, K>& points,
                      const Eigen::Matrix<double, K * Dim, 1>& local_x, Eigen::VectorXd* gradient,
                      HessianSink hessian, Eigen::Matrix<double, Dim, Dim>* virial = nullptr)
{
    if (virial) {
        const auto d =
            hessian ? local_hessian<K * Dim>(term, local_x) : local_gradient<K * Dim>(term, local_x);
        for (int k = 0; k < K; ++k)
            *virial -= local_x.template segment<Dim>(Dim * k) *
                       d.gradient.template segment<Dim>(Dim * k).transpose();
        add_local_derivatives<Dim, K>(d, points, local_x, gradient, hessian);
        return d.value;
    }
    if (hessian) {
        const auto d = local_hessian<K * Dim>(term, local_x);
        add_local_derivatives<Dim, K>(d, points, local_x, gradient, hessian);
        return d.value;
    }
    if (gradient) {
        const auto d = local_gradient<K * Dim>(term, local_x);
        scatter<Dim, K>(d, points, 1.0, gradient, nullptr);
        return d.value;
    }
    return local_value<K * Dim>(term, local_x);
}

} // namespace softgrain::dpm
