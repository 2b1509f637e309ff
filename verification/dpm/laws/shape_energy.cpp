// DPM eq. (9.1): every term of the 2D shape energy. Forces are minus the gradient of the energy and the
// Hessian is the derivative of the gradient (central finite differences on random configurations);
// the analytic gradients of the gradient-only (FIRE) path and their Jacobians equal the AutoDiff gradients
// and Hessians to round-off; the sparse Hessian equals the dense one to the bit; the shape
// parameter of section 9.3.1 and its minimum N tan(pi/N)/pi.
#include "dpm/laws/shape_energy.hpp"
#include "core/rng.hpp"
#include "support/derivatives.hpp"
#include "support/tolerance.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <numbers>
#include <vector>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_against_central_differences;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

const double pi = std::numbers::pi;

// A regular n-gon of area `area` (CCW) with every coordinate displaced by up to `noise` times the edge.
Eigen::VectorXd perturbed_polygon(int n, double area, double noise, Rng& rng)
{
    const double r = regular_polygon_radius(n, area);
    const double edge = 2 * r * std::sin(pi / n);
    Eigen::VectorXd x(2 * n);
    const double phase = rng.uniform(0, 2 * pi);
    for (int i = 0; i < n; ++i) {
        x(2 * i) = 0.3 + r * std::cos(phase + 2 * pi * i / n) + noise * edge * rng.uniform(-1, 1);
        x(2 * i + 1) = -0.2 + r * std::sin(phase + 2 * pi * i / n) + noise * edge * rng.uniform(-1, 1);
    }
    return x;
}

ShapeParameters random_parameters(int n, Rng& rng)
{
    ShapeParameters s;
    s.ka = rng.uniform(0.5, 2.0);
    s.a0 = rng.uniform(0.8, 1.2);
    s.kl = rng.uniform(0.5, 2.0);
    s.l0 = rng.uniform(0.8, 1.2) * std::sqrt(4 * pi * s.a0 * 1.1) / n;
    s.kb = rng.uniform(0.5, 2.0);
    s.theta0 = rng.uniform(0.5, 1.5) * 2 * pi / n;
    s.gamma = rng.uniform(0.5, 2.0);
    return s;
}

// Central differences of the energy (-> gradient) and of the AutoDiff gradient (-> Hessian) of one term.
void check_derivatives(const ShapeParameters& s, const Eigen::VectorXd& x, unsigned term)
{
    const int n = static_cast<int>(x.size() / 2), dofs = static_cast<int>(x.size());
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const double energy = shape_energy(s, x, 0, n, &g, &h, term);
    // The energy alone and with derivatives is the same code: equal to round-off.
    CHECK_CLOSE(shape_energy(s, x, 0, n, nullptr, nullptr, term), energy, (Tolerance{10 * round_off, 0}));
    check_against_central_differences(
        [&](const Eigen::VectorXd& y, Eigen::VectorXd* gy, Eigen::MatrixXd* hy) {
            return shape_energy(s, y, 0, n, gy, hy, term);
        },
        x, g, h);
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    const double h_scale = std::max(1.0, h.cwiseAbs().maxCoeff());
    // The Hessian of an energy is symmetric (exact in AutoDiff up to round-off).
    CHECK_CLOSE((h - h.transpose()).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 100 * round_off * h_scale}));
    // Translation invariance: the forces sum to zero.
    CHECK_CLOSE(g.reshaped(2, n).rowwise().sum().norm(), 0.0, (Tolerance{0, 100 * round_off * g_scale}));
}

} // namespace

TEST_CASE(
    "forces = -grad U and Hessian = d(grad U) for each term of eq. (9.1), random polygons [DPM eq. (9.1)]")
{
    Rng rng(20251);
    const std::pair<unsigned, const char*> terms[] = {{area_term, "area"},
                                                      {edge_term, "edge length"},
                                                      {bending_term, "bending"},
                                                      {line_tension_term, "line tension"},
                                                      {all_shape_terms, "all"}};
    for (int n : {3, 5, 8, 13}) {
        for (int sample = 0; sample < 3; ++sample) {
            const ShapeParameters s = random_parameters(n, rng);
            const Eigen::VectorXd x = perturbed_polygon(n, s.a0 * rng.uniform(0.7, 1.3), 0.15, rng);
            for (const auto& [term, name] : terms) {
                CAPTURE(n);
                CAPTURE(name);
                check_derivatives(s, x, term);
            }
        }
    }
}

TEST_CASE("each term of eq. (9.1) against its closed form on a regular polygon [DPM eq. (9.1)]")
{
    const int n = 7;
    const double a0 = 1.3, area = 1.1;
    const double r = regular_polygon_radius(n, area), l = 2 * r * std::sin(pi / n);
    Eigen::VectorXd x(2 * n);
    for (int i = 0; i < n; ++i)
        x.segment<2>(2 * i) = r * Eigen::Vector2d(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n));
    ShapeParameters s{2.0, a0, 3.0, 0.4, 5.0, 0.7, 0.25};
    // Exact closed forms evaluated in floating point: agreement to round-off of sums over n terms.
    const Tolerance exact{1e3 * round_off, 0};
    CHECK_CLOSE(particle_area(x, 0, n), area, exact);
    CHECK_CLOSE(shape_energy(s, x, 0, n, nullptr, nullptr, area_term), 0.5 * s.ka * (area - a0) * (area - a0),
                exact);
    CHECK_CLOSE(shape_energy(s, x, 0, n, nullptr, nullptr, edge_term),
                n * 0.5 * s.kl * (l - s.l0) * (l - s.l0), exact);
    CHECK_CLOSE(shape_energy(s, x, 0, n, nullptr, nullptr, bending_term),
                n * 0.5 * s.kb * (2 * pi / n - s.theta0) * (2 * pi / n - s.theta0), exact);
    CHECK_CLOSE(shape_energy(s, x, 0, n, nullptr, nullptr, line_tension_term), s.gamma * n * l, exact);
}

TEST_CASE(
    "shape parameter of the regular N-gon is N tan(pi/N)/pi, the minimum over N-gons, -> 1 [DPM sec. 9.3.1]")
{
    // Reference values from the inventory (derived): N = 5 -> 1.15633, 8 -> 1.05479, 10 -> 1.03425.
    CHECK_CLOSE(minimum_shape_parameter(5), 1.15633, (Tolerance{5e-6, 0}));
    CHECK_CLOSE(minimum_shape_parameter(8), 1.05479, (Tolerance{5e-6, 0}));
    CHECK_CLOSE(minimum_shape_parameter(10), 1.03425, (Tolerance{5e-6, 0}));
    // N tan(pi/N)/pi = 1 + pi^2/(3 N^2) + O(N^-4).
    CHECK_CLOSE(minimum_shape_parameter(1000) - 1, pi * pi / 3e6, (Tolerance{1e-5, 0}));
    Rng rng(7);
    for (int n : {3, 5, 8, 20}) {
        const Eigen::VectorXd regular = perturbed_polygon(n, 1.0, 0.0, rng);
        CHECK_CLOSE(shape_parameter(particle_perimeter(regular, 0, n), particle_area(regular, 0, n)),
                    minimum_shape_parameter(n), (Tolerance{1e3 * round_off, 0}));
        for (int sample = 0; sample < 20; ++sample) {
            const Eigen::VectorXd x = perturbed_polygon(n, 1.0, 0.1, rng);
            CHECK(shape_parameter(particle_perimeter(x, 0, n), particle_area(x, 0, n)) >=
                  minimum_shape_parameter(n));
        }
    }
}

TEST_CASE("Table 9.1 rest shapes: an elastic shell at A0 = A_min is force-free as a regular polygon [DPM "
          "Table 9.1]")
{
    const int n = 10;
    const ShapeParameters s =
        table_9_1_parameters(ShapeModel::shell, n, 1.0, minimum_shape_parameter(n), ShapeStiffness{});
    Rng rng(3);
    const Eigen::VectorXd x = perturbed_polygon(n, 1.0, 0.0, rng);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(2 * n);
    // The rest values are met to round-off (l0 from A0 = A_min reproduces the regular polygon's edge).
    CHECK_CLOSE(shape_energy(s, x, 0, n, &g, nullptr), 0.0, (Tolerance{0, 1e3 * round_off * round_off}));
    CHECK_CLOSE(g.norm(), 0.0, (Tolerance{0, 1e3 * round_off}));
    CHECK_CLOSE(n * s.l0, particle_perimeter(x, 0, n), (Tolerance{1e3 * round_off, 0}));
}

TEST_CASE("analytic slopes of edge length, shoelace term and turning angle and their Jacobians = AutoDiff "
          "gradients and Hessians to round-off [DPM eq. (9.1)]")
{
    // The same derivatives in two roundings: the analytic slopes (shape_energy.hpp) in double and, through
    // their forward-mode Jacobian, the Hessian (local_hessian_from_slope), against forward AutoDiff of the
    // measures themselves, once and nested. Each gradient component is a quotient or product of two or three
    // O(1) differences of coordinates, so they agree to a few eps of the measure's gradient scale (its
    // largest component); 16 eps leaves room for the different operation order of AutoDiff's atan2
    // derivative (d cross dot - cross d dot)/(cross^2 + dot^2), while a wrong sign or term is an O(1)
    // relative error. A Hessian entry is one more such quotient (derivatives of 1/|e|^2 and of e/|e|), so
    // 64 eps of the Hessian's scale. The values are the same double code in both. Random points of
    // [-1, 1]^2: turning angles over (-pi, pi), both signs and close to +-pi.
    Rng rng(91201);
    const auto point = [&rng] { return Eigen::Vector2d(rng.uniform(-1, 1), rng.uniform(-1, 1)); };
    const auto check = [](const auto& measure, const auto& slope, const auto& x) {
        constexpr int n = std::decay_t<decltype(x)>::RowsAtCompileTime;
        const auto autodiff = local_hessian<n>(measure, x);
        const auto analytic = local_hessian_from_slope<n>(measure, slope, x);
        const double scale = autodiff.gradient.cwiseAbs().maxCoeff();
        CHECK_CLOSE(analytic.value, autodiff.value, (Tolerance{0, 4 * round_off * std::abs(autodiff.value)}));
        CHECK_CLOSE((slope(x, measure(x)) - autodiff.gradient).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 16 * round_off * scale}));
        // The value part of the AutoDiff sweep: the same formulas, grouped as Eigen's AutoDiff takes them.
        CHECK_CLOSE((analytic.gradient - slope(x, measure(x))).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 4 * round_off * scale}));
        CHECK_CLOSE((analytic.hessian - autodiff.hessian).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 64 * round_off * autodiff.hessian.cwiseAbs().maxCoeff()}));
        CHECK(analytic.hessian == analytic.hessian.transpose());
    };
    double smallest_angle = 0, largest_angle = 0;
    for (int trial = 0; trial < 500; ++trial) {
        Eigen::Matrix<double, 4, 1> edge;
        edge << point(), point();
        check(edge_length, edge_length_slope, edge);
        check(shoelace_term, shoelace_term_slope, edge);
        Eigen::Matrix<double, 6, 1> corner;
        corner << point(), point(), point();
        check(turning_angle, turning_angle_slope, corner);
        smallest_angle = std::min(smallest_angle, turning_angle(corner));
        largest_angle = std::max(largest_angle, turning_angle(corner));
    }
    CHECK(smallest_angle < -3.0);
    CHECK(largest_angle > 3.0);
}

TEST_CASE("the gradient-only path of eq. (9.1) (FIRE) = the gradient beside the Hessian, and the sparse "
          "Hessian = the dense one, each term, k_b = 0 and k_b > 0, random polygons [DPM eq. (9.1)]")
{
    // Random non-regular polygons (vertices displaced by up to 30 % of the edge: concave corners too) of
    // 3 ... 22 vertices, stored as the second particle of a flat array (so the particle's offset is
    // exercised), with random stiffnesses and rest values; floppy-like k_b = 0 and shell-like k_b > 0.
    // Both paths take the same analytic slopes: the gradient-only path sums k (q - q0) grad q element by
    // element and, for the area, the slopes of the shoelace terms in a second pass; the Hessian's path
    // per term, through the value part of the AutoDiff sweep, and grad a first: round-off of the sums over
    // the <= 3 local terms at a vertex and of the product k_a (a - a0) grad a, where a - a0 carries the
    // rounding of the O(n)-term shoelace sum (n eps |a|); hence 100 eps of the gradient's scale (its
    // largest component, at least 1 of these O(1) units). A wrong sign, factor or index is an O(1) relative
    // error. Into a sparse sink the particle's Hessian goes as one dense block (with_dense_block): the
    // same additions in the same order as into the dense matrix, so the same numbers to the bit, one
    // triplet per entry.
    Rng rng(91202);
    const std::pair<unsigned, const char*> terms[] = {{area_term, "area"},
                                                      {edge_term, "edge length"},
                                                      {bending_term, "bending"},
                                                      {line_tension_term, "line tension"},
                                                      {all_shape_terms, "all"}};
    for (int n : {3, 6, 16, 22}) {
        for (double kb_factor : {0.0, 1.0}) {
            ShapeParameters s = random_parameters(n, rng);
            s.kb *= kb_factor;
            const Eigen::VectorXd before = perturbed_polygon(5, 1.0, 0.1, rng);
            const Eigen::VectorXd polygon = perturbed_polygon(n, s.a0 * rng.uniform(0.7, 1.3), 0.3, rng);
            Eigen::VectorXd x(before.size() + polygon.size());
            x << before, polygon;
            const int first = 5, dofs = static_cast<int>(x.size());
            for (const auto& [term, name] : terms) {
                CAPTURE(n);
                CAPTURE(s.kb);
                CAPTURE(name);
                Eigen::VectorXd g_with_hessian = Eigen::VectorXd::Zero(dofs),
                                g_analytic = Eigen::VectorXd::Zero(dofs);
                Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
                const double energy = shape_energy(s, x, first, n, &g_with_hessian, &h, term);
                CHECK_CLOSE(shape_energy(s, x, first, n, &g_analytic, nullptr, term), energy,
                            (Tolerance{10 * round_off, 100 * round_off}));
                const double scale = std::max(1.0, g_with_hessian.cwiseAbs().maxCoeff());
                CHECK_CLOSE((g_analytic - g_with_hessian).cwiseAbs().maxCoeff(), 0.0,
                            (Tolerance{0, 100 * round_off * scale}));
                // Nothing outside the particle.
                CHECK(g_analytic.head(2 * first).cwiseAbs().maxCoeff() == 0.0);
                CHECK(h.topRows(2 * first).cwiseAbs().maxCoeff() == 0.0);
                CHECK(h.leftCols(2 * first).cwiseAbs().maxCoeff() == 0.0);
                // The same particle alone: the same gradient and Hessian, the offset only moves them (same
                // operations on the same numbers).
                Eigen::VectorXd g_alone = Eigen::VectorXd::Zero(2 * n);
                Eigen::MatrixXd h_alone = Eigen::MatrixXd::Zero(2 * n, 2 * n);
                shape_energy(s, polygon, 0, n, &g_alone, &h_alone, term);
                CHECK((g_with_hessian.tail(2 * n) - g_alone).cwiseAbs().maxCoeff() == 0.0);
                CHECK((h.bottomRightCorner(2 * n, 2 * n) - h_alone).cwiseAbs().maxCoeff() == 0.0);
                std::vector<Eigen::Triplet<double>> triplets;
                shape_energy(s, x, first, n, nullptr, &triplets, term);
                CHECK(triplets.size() == static_cast<std::size_t>(4 * n * n));
                Eigen::SparseMatrix<double> sparse(dofs, dofs);
                sparse.setFromTriplets(triplets.begin(), triplets.end());
                CHECK((Eigen::MatrixXd(sparse) - h).cwiseAbs().maxCoeff() == 0.0);
            }
        }
    }
}
