// DPM eq. (9.1): every term of the 2D shape energy. Forces are minus the gradient of the energy and the
// Hessian is the derivative of the gradient (central finite differences on random configurations);
// the shape parameter of section 9.3.1 and its minimum N tan(pi/N)/pi.
#include "dpm/shape_energy.hpp"
#include "core/rng.hpp"
#include "support/derivatives.hpp"
#include "support/tolerance.hpp"

#include <numbers>

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
