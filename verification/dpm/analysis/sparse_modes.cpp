// The sparse dynamical matrix (eq. 9.28) and its lowest modes by shift-and-invert Lanczos (sparse_modes.hpp)
// against the dense matrix and Eigen's dense SelfAdjointEigenSolver, on small jammed packings where both run.
//
// Matrix: the sparse one is summed from the same local-term blocks as the dense one (HessianSink), only in a
// different order (setFromTriplets sums each entry's terms in insertion order, the dense matrix as they come,
// and the rank-one shape blocks are added at once in both), so the entries may differ by the round-off of
// re-ordered sums: at most (terms per entry) eps max|M_ij|; 64 eps max|M_ij| bounds it (an entry of a
// 3D vertex gathers its faces, edges, volume and contacts: a few tens of terms).
//
// Spectrum: a backward-stable dense eigensolver returns each eigenvalue within p(n) eps ||M||_2, n eps ||M||
// the usual bound (the zero-mode round-off bound, zero_mode_threshold); the sparse path solves with the LDL^T
// of the positive definite M - sigma (backward stable: the same bound) and stops at a residual of
// 1e-12 ||M - sigma||. The lowest eigenvalues then agree within 2 n eps lambda_max + 1e-12 lambda_max. The
// eigenvectors of a cluster of eigenvalues (closer than 1e-6 lambda_max: the zero modes, degenerate to
// round-off, are one) are only defined as a subspace; the sine of the largest principal angle between the
// dense and the sparse subspace is bounded by Davis-Kahan, (residual) / (gap to the rest of the spectrum),
// with the residual bound above.
#include "dpm/analysis/sparse_modes.hpp"
#include "core/errors.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "support/packings.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::polished_packing2d;
using softgrain::verification::polished_packing3d;
using softgrain::verification::round_off;

namespace {

void check_same_matrix(const Eigen::MatrixXd& dense, const Eigen::SparseMatrix<double>& sparse)
{
    const double largest = dense.cwiseAbs().maxCoeff();
    const double difference = (Eigen::MatrixXd(sparse) - dense).cwiseAbs().maxCoeff();
    MESSAGE("n = " << dense.rows() << ", non-zeros " << sparse.nonZeros() << ", max|M| " << largest
                   << ", max|sparse - dense| " << difference);
    CHECK(largest > 0);
    CHECK(difference <= 64 * round_off * largest);
}

// Sine of the largest principal angle between the spans of the orthonormal columns of a and b.
double largest_angle_sine(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
    const Eigen::MatrixXd outside = b - a * (a.transpose() * b);
    return Eigen::JacobiSVD<Eigen::MatrixXd>(outside).singularValues()(0);
}

// The lowest modes of m by the sparse solver against the dense spectrum (see the header comment): at least
// `at_least` of them and `beyond_zero` past the dense zero modes (how many a packing has depends on its
// rattlers, i.e. on the packing FIRE reaches), more where that count would split a cluster (whose subspace
// must be compared whole).
LowestModes check_lowest_modes(const Eigen::MatrixXd& dense, const Eigen::SparseMatrix<double>& sparse,
                               int at_least, double eigenvalue_unit, double paper_threshold)
{
    constexpr int beyond_zero = 8;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(dense);
    const Eigen::VectorXd& exact = reference.eigenvalues();
    const auto n = dense.rows();
    const double lambda_max = exact(n - 1);
    const double cluster_gap = 1e-6 * lambda_max;
    const double threshold = zero_mode_threshold(exact / eigenvalue_unit, paper_threshold);
    const SpectrumCounts dense_counts = count_modes(exact / eigenvalue_unit, threshold);
    int count = std::max(at_least, dense_counts.first_positive() + beyond_zero);
    while (count < n && exact(count) - exact(count - 1) < cluster_gap)
        ++count;
    REQUIRE(count < n);
    const LowestModes lowest = lowest_modes(sparse, count);
    const Eigen::VectorXd& lambda = lowest.spectrum.eigenvalues;
    const double residual = (2 * static_cast<double>(n) * round_off + 1e-12) * lambda_max;
    MESSAGE("n = " << n << ", modes " << count << ", shift " << lowest.shift << " after "
                   << lowest.factorizations << " factorizations, restarts " << lowest.restarts << ", solves "
                   << lowest.solves << ", max eigenvalue error "
                   << (lambda - exact.head(count)).cwiseAbs().maxCoeff() << " (allowed " << residual << ")");
    REQUIRE(lambda.size() == count);
    CHECK(lowest.shift < exact(0));
    CHECK(std::abs(lowest.largest_eigenvalue - lambda_max) <= residual);
    for (int k = 0; k < count; ++k) {
        CAPTURE(k);
        CHECK(std::abs(lambda(k) - exact(k)) <= residual);
    }
    // Zero modes: the same count against the same threshold (max|lambda| from the Lanczos lambda_max).
    const double sparse_threshold = zero_mode_threshold(
        n, std::max(std::abs(lambda(0)), lowest.largest_eigenvalue) / eigenvalue_unit, paper_threshold);
    const SpectrumCounts sparse_counts = count_modes(lambda / eigenvalue_unit, sparse_threshold);
    MESSAGE("zero modes dense " << dense_counts.zero << ", sparse " << sparse_counts.zero);
    CHECK(dense_counts.zero > 0);
    CHECK(sparse_counts.first_positive() < count); // the count saw a non-zero mode: it is complete
    CHECK(sparse_counts.zero == dense_counts.zero);
    CHECK(sparse_counts.negative == dense_counts.negative);
    // Eigenvectors: cluster by cluster of the dense spectrum.
    int clusters = 0;
    for (int first = 0; first < count;) {
        int end = first + 1;
        while (end < n && exact(end) - exact(end - 1) < cluster_gap)
            ++end;
        CAPTURE(first);
        CAPTURE(end);
        REQUIRE(end <= count); // count ends a cluster
        const double below = first > 0 ? exact(first) - exact(first - 1) : lambda_max;
        const double above = end < n ? exact(end) - exact(end - 1) : lambda_max;
        const double sine = largest_angle_sine(reference.eigenvectors().middleCols(first, end - first),
                                               lowest.spectrum.eigenvectors.middleCols(first, end - first));
        CHECK(sine <= residual / std::min(below, above));
        ++clusters;
        first = end;
    }
    MESSAGE(clusters << " clusters of eigenvectors compared, " << lowest.passes << " Lanczos passes");
    return lowest;
}

} // namespace

TEST_CASE("sparse dynamical matrix equals the dense one: 2D and 3D, rough and smooth contacts [eq. 9.28]")
{
    SUBCASE("2D surface-tension packing, N = 16")
    {
        JamResult r = polished_packing2d(JamModel::surface_tension, 16, 2);
        check_same_matrix(dynamical_matrix(r.system, r.x), sparse_dynamical_matrix(r.system, r.x));
        // Smooth contacts (eqs. 9.5-9.9) at the same overlapping configuration.
        r.system.interaction = InteractionKind::smooth;
        REQUIRE(total_energy(r.system, r.x, nullptr, nullptr, interaction_part) > 0);
        check_same_matrix(dynamical_matrix(r.system, r.x), sparse_dynamical_matrix(r.system, r.x));
    }
    SUBCASE("3D icosahedral shells, N = 8")
    {
        Jam3dResult j = polished_packing3d(8, 3);
        for (const InteractionKind contact : {InteractionKind::rough, InteractionKind::smooth}) {
            j.system.interaction = contact;
            CAPTURE(static_cast<int>(contact));
            REQUIRE(interaction_energy3d(j.system, j.x, nullptr, nullptr) > 0);
            Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
            total_energy3d(j.system, j.x, nullptr, &dense);
            check_same_matrix(dense, sparse_dynamical_matrix3d(j.system, j.x));
        }
    }
}

TEST_CASE("lowest modes by shift-and-invert Lanczos equal the dense spectrum's [DPM sec. 9.4.3]")
{
    SUBCASE("2D surface-tension packings, N = 16 and 32")
    {
        for (const int particles : {16, 32}) {
            CAPTURE(particles);
            const JamResult r = polished_packing2d(JamModel::surface_tension, particles, 2);
            check_lowest_modes(dynamical_matrix(r.system, r.x), sparse_dynamical_matrix(r.system, r.x), 60,
                               r.pressure_unit, 1e-13);
        }
    }
    SUBCASE("3D icosahedral shells, N = 8")
    {
        const Jam3dResult j = polished_packing3d(8, 3);
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
        total_energy3d(j.system, j.x, nullptr, &dense);
        const Eigen::SparseMatrix<double> sparse = sparse_dynamical_matrix3d(j.system, j.x);
        check_lowest_modes(dense, sparse, 40, j.eigenvalue_unit, 1e-10);
        // Modes 48 ... 65 form one cluster (18 eigenvalues closer than 1e-6 lambda_max in turn, the
        // packing's near symmetry); single-vector Lanczos found only part of it and returned 5 higher modes
        // in their place (measured before deflation). The deflated passes must find the whole cluster.
        const LowestModes cluster = check_lowest_modes(dense, sparse, 66, j.eigenvalue_unit, 1e-10);
        CHECK(cluster.passes > 1);
    }
}

TEST_CASE("shift-and-invert Lanczos below negative modes: a shifted chain Laplacian, eigenvalues analytic")
{
    // M = L - c with L the Dirichlet chain Laplacian (tridiagonal 2, -1): lambda_k = 2 - 2 cos(pi k / (n + 1))
    // - c, k = 1 ... n. With c = 0.01 the lowest twelve are negative (a saddle's instabilities), far below
    // the first shift -1e-6 R (R = 4 + c), so the LDL^T of M - sigma shows negative pivots until sigma is
    // lowered past them. Tolerance: the residual bound of the header comment, 1e-12 (R) plus n eps R.
    const int n = 400;
    const double c = 0.01;
    std::vector<Eigen::Triplet<double>> triplets;
    for (int i = 0; i < n; ++i) {
        triplets.emplace_back(i, i, 2.0 - c);
        if (i + 1 < n) {
            triplets.emplace_back(i, i + 1, -1.0);
            triplets.emplace_back(i + 1, i, -1.0);
        }
    }
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(triplets.begin(), triplets.end());
    const LowestModes lowest = lowest_modes(m, 10);
    const double pi = std::acos(-1.0);
    const double tolerance = (1e-12 + n * round_off) * (4 + c);
    MESSAGE("shift " << lowest.shift << " after " << lowest.factorizations << " factorizations");
    CHECK(lowest.factorizations > 1);
    CHECK(lowest.shift < 2 - 2 * std::cos(pi / (n + 1)) - c);
    for (int k = 1; k <= 10; ++k) {
        CAPTURE(k);
        CHECK(std::abs(lowest.spectrum.eigenvalues(k - 1) - (2 - 2 * std::cos(pi * k / (n + 1)) - c)) <=
              tolerance);
    }
    CHECK(std::abs(lowest.largest_eigenvalue - (2 - 2 * std::cos(pi * n / (n + 1)) - c)) <= tolerance);
}
