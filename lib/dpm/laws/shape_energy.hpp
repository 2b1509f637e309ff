// Shape energy of a 2D deformable particle, DPM eq. (9.1):
//
//   U_shape = k_a/2 (a - a0)^2 + sum_i k_l/2 (l_i - l0)^2 + sum_i k_b/2 (theta_i - theta0)^2 + gamma p
//
// a: signed (shoelace) area of the polygon, positive for counter-clockwise vertices; l_i: length of the
// edge from vertex i-1 to vertex i; theta_i: turning (bending) angle at vertex i between the edges
// (i-1 -> i) and (i -> i+1), atan2(cross, dot), so a convex CCW regular N-gon has theta_i = 2 pi/N;
// p = sum_i l_i (line tension gamma). Units: lengths [L], k_a [E/L^4], k_l [E/L^2], k_b [E], gamma [E/L].
// Sign: U_shape >= 0 for k_a, k_l, k_b, gamma >= 0; shape_energy adds the gradient dU/dx = minus the forces.
// Valid for a simple (not self-intersecting) counter-clockwise polygon, unwrapped, with edges of non-zero
// length (the gradient of l_i is singular at l_i = 0) and turning angles away from +-pi, where theta_i
// jumps by 2 pi (an edge folded back onto its neighbour). A clockwise polygon has a < 0.
//
// Each term is written once as a local measure of the coordinates it depends on, with its analytic
// gradient (its "slope"), both templated on the scalar: the forces are the slopes in double, the exact
// Hessian is the slopes' forward-mode Jacobian (local_derivatives.hpp). The area term is a penalty of a sum
// of local measures (shoelace terms); its derivatives follow by the chain rule from theirs. 3D shells
// (eq. 9.2, shape_energy3d.hpp) reuse harmonic_penalty, measure_term and the penalty of a sum with a face
// volume.
#pragma once

#include "dpm/laws/local_derivatives.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace softgrain::dpm {

// k/2 (q - q0)^2: the form of every penalty of eqs. (9.1) and (9.2).
template <class Scalar>
Scalar harmonic_penalty(double k, const Scalar& q, double q0)
{
    const Scalar deviation = q - q0;
    return Scalar(0.5 * k) * deviation * deviation;
}

// The local measures of eq. (9.1). Each is a named generic callable (not a function template) so that it
// can be handed to the penalty and tension terms below and to the AutoDiff machinery.

// Length of the edge between the two points of x = (x0, y0, x1, y1).
inline constexpr auto edge_length = []<class Scalar>(const Eigen::Matrix<Scalar, 4, 1>& x) -> Scalar {
    using std::sqrt;
    const Scalar dx = x(2) - x(0), dy = x(3) - x(1);
    return Scalar(sqrt(dx * dx + dy * dy));
};

// Turning angle at the middle point of x = (previous, vertex, next): the signed angle from the incoming
// edge to the outgoing edge, in (-pi, pi]; positive where the polygon turns counter-clockwise.
inline constexpr auto turning_angle = []<class Scalar>(const Eigen::Matrix<Scalar, 6, 1>& x) -> Scalar {
    using std::atan2;
    const Scalar ix = x(2) - x(0), iy = x(3) - x(1), ox = x(4) - x(2), oy = x(5) - x(3);
    const Scalar cross = ix * oy - iy * ox, dot = ix * ox + iy * oy;
    return Scalar(atan2(cross, dot));
};

// One shoelace term (x0 y1 - x1 y0)/2 of the polygon area; the sum over the edges is the signed area.
inline constexpr auto shoelace_term = []<class Scalar>(const Eigen::Matrix<Scalar, 4, 1>& x) -> Scalar {
    return Scalar(0.5) * (x(0) * x(3) - x(2) * x(1));
};

// Analytic first derivatives ("slopes") of the three measures above, generic in the scalar as the measures
// are. In double they are the gradient-only path (FIRE): the AutoDiff gradient of the same measures costs
// several times more (decision dpm-2d-analytic-gradient). In first-order AutoDiff their Jacobian is the
// measures' Hessian (local_hessian_from_slope), which costs a fraction of nested AutoDiff of the measures.
// Verified against the AutoDiff gradients and Hessians of the measures to round-off
// (verification/dpm/laws/shape_energy.cpp).
//   grad edge_length: d l/d r1 = (r1 - r0)/l = -d l/d r0; undefined at l = 0;
//   grad shoelace_term = (y1, -x1, -y0, x0)/2;
//   grad turning_angle: theta = phi(o) - phi(i) (mod 2 pi) with phi(e) the polar angle of an edge
//     e = (e_x, e_y), d phi/d e = (-e_y, e_x)/|e|^2, for the incoming edge i = r1 - r0 and the outgoing
//     edge o = r2 - r1: d theta/d r0 = (-i_y, i_x)/|i|^2, d theta/d r2 = (-o_y, o_x)/|o|^2,
//     d theta/d r1 = -(d theta/d r0 + d theta/d r2) (translation invariance); undefined where an edge
//     has length 0.
// A slope takes the measure's value q at x too, which the length's (and the triangle area's) reuses instead
// of a second square root; the others ignore it.
// Inline lambdas: they run at every vertex of every FIRE force evaluation.
inline constexpr auto edge_length_slope =
    []<class Scalar>(const Eigen::Matrix<Scalar, 4, 1>& x,
                     const Scalar& length) -> Eigen::Matrix<Scalar, 4, 1> {
    const Eigen::Matrix<Scalar, 2, 1> r = x.template segment<2>(2) - x.template segment<2>(0);
    const Eigen::Matrix<Scalar, 2, 1> unit = r / length;
    Eigen::Matrix<Scalar, 4, 1> g;
    g << -unit, unit;
    return g;
};

inline constexpr auto shoelace_term_slope = []<class Scalar>(const Eigen::Matrix<Scalar, 4, 1>& x,
                                                             const Scalar&) -> Eigen::Matrix<Scalar, 4, 1> {
    Eigen::Matrix<Scalar, 4, 1> g;
    g << Scalar(0.5) * x(3), Scalar(-0.5) * x(2), Scalar(-0.5) * x(1), Scalar(0.5) * x(0);
    return g;
};

inline constexpr auto turning_angle_slope = []<class Scalar>(const Eigen::Matrix<Scalar, 6, 1>& x,
                                                             const Scalar&) -> Eigen::Matrix<Scalar, 6, 1> {
    using Vector = Eigen::Matrix<Scalar, 2, 1>;
    const Vector incoming = x.template segment<2>(2) - x.template segment<2>(0);
    const Vector outgoing = x.template segment<2>(4) - x.template segment<2>(2);
    // d phi/d e = (-e_y, e_x)/|e|^2 for the polar angle phi of an edge e.
    const Scalar in2 = incoming.squaredNorm(), out2 = outgoing.squaredNorm();
    const Vector g0 = Vector(-incoming.y(), incoming.x()) / in2;
    const Vector g2 = Vector(-outgoing.y(), outgoing.x()) / out2;
    Eigen::Matrix<Scalar, 6, 1> g;
    g << g0, -(g0 + g2), g2;
    return g;
};

// One local measure q of eq. (9.1) or (9.2) over `points` that enters the energy as
// U = k/2 (q - q0)^2 + gamma q (an edge's length for k_l and gamma at once, a corner's turning angle; a
// face's area, a hinge's angle), with dU = (k (q - q0) + gamma) dq and d^2U = k dq dq^T + (k (q - q0) +
// gamma) d^2q: its value alone, with the gradient from the analytic slope (FIRE), or with the Hessian too,
// the slope's forward-mode Jacobian. Adds the derivatives where `gradient` and `hessian` ask; a term that
// is switched off has k = 0 or gamma = 0.
template <int Dim, int K, class Measure, class Slope>
double measure_term_with_hessian(const Measure& measure, const Slope& slope, const std::array<int, K>& points,
                                 const Eigen::VectorXd& x, double k, double rest, double gamma,
                                 Eigen::VectorXd* gradient, HessianSink hessian)
{
    const Eigen::Matrix<double, K * Dim, 1> local = gather<Dim, K>(x, points);
    const LocalDerivatives<K* Dim> q = local_hessian_from_slope<K * Dim>(measure, slope, local);
    const double weight = k * (q.value - rest) + gamma;
    LocalDerivatives<K * Dim> term;
    term.value = harmonic_penalty(k, q.value, rest) + gamma * q.value;
    term.gradient = weight * q.gradient;
    term.hessian = k * q.gradient * q.gradient.transpose() + weight * q.hessian;
    add_local_derivatives<Dim, K>(term, points, local, gradient, hessian);
    return term.value;
}

// The value and gradient path is kept apart from the Hessian's and inline: it runs at every edge, corner,
// face and hinge of every FIRE force evaluation, where a call per term made a 2D one 16 % slower.
template <int Dim, int K, class Measure, class Slope>
inline double measure_term(const Measure& measure, const Slope& slope, const std::array<int, K>& points,
                           const Eigen::VectorXd& x, double k, double rest, double gamma,
                           Eigen::VectorXd* gradient, const HessianSink& hessian)
{
    if (hessian)
        return measure_term_with_hessian<Dim, K>(measure, slope, points, x, k, rest, gamma, gradient,
                                                 hessian);
    const Eigen::Matrix<double, K * Dim, 1> local = gather<Dim, K>(x, points);
    const double q = measure(local);
    if (gradient) scatter_gradient<Dim, K>(slope(local, q), points, k * (q - rest) + gamma, *gradient);
    return harmonic_penalty(k, q, rest) + gamma * q;
}

// k/2 (Q - Q0)^2 of a sum Q = sum_j q_j of local measures over the `elements` point sets points_of(j),
// j = 0 ... elements - 1 (the area of eq. 9.1 over the shoelace terms, the volume of eq. 9.2 over the face
// volumes), all of them among the `count` points first ... first + count - 1 of x (one particle), with its
// gradient k (Q - Q0) grad Q and Hessian k (grad Q grad Q^T + (Q - Q0) hess Q): grad Q and hess Q are
// assembled in the particle's own coordinates from the local measures' slopes and their Jacobians.
template <int Dim, int K, class Measure, class Slope, class PointsOf>
double penalty_of_sum_with_hessian(double k, double rest, const Measure& measure, const Slope& slope,
                                   int elements, const PointsOf& points_of, int first, int count,
                                   const Eigen::VectorXd& x, Eigen::VectorXd* gradient, HessianSink hessian)
{
    const int dofs = Dim * count;
    Eigen::VectorXd grad_sum = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd hess_sum = Eigen::MatrixXd::Zero(dofs, dofs);
    double sum = 0;
    for (int j = 0; j < elements; ++j) {
        const std::array<int, K> points = points_of(j);
        std::array<int, K> own_points; // indices within the particle
        for (int a = 0; a < K; ++a)
            own_points[a] = points[a] - first;
        const LocalDerivatives<K* Dim> q =
            local_hessian_from_slope<K * Dim>(measure, slope, gather<Dim, K>(x, points));
        sum += q.value;
        scatter<Dim, K>(q, own_points, 1.0, &grad_sum, &hess_sum);
    }
    const double deviation = sum - rest;
    if (gradient) gradient->segment(Dim * first, dofs) += k * deviation * grad_sum;
    hessian.add(Dim * first, Dim * first, k * (grad_sum * grad_sum.transpose() + deviation * hess_sum));
    return harmonic_penalty(k, sum, rest);
}

// The same penalty, its value and (when `gradient` is given) its gradient in two passes, the sum Q and then
// k (Q - Q0) grad q_j scattered element by element (no buffer); the Hessian, when asked for, as above.
// Inline for FIRE, as measure_term.
template <int Dim, int K, class Measure, class Slope, class PointsOf>
inline double penalty_of_sum(double k, double rest, const Measure& measure, const Slope& slope, int elements,
                             const PointsOf& points_of, int first, int count, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient, const HessianSink& hessian)
{
    if (hessian)
        return penalty_of_sum_with_hessian<Dim, K>(k, rest, measure, slope, elements, points_of, first, count,
                                                   x, gradient, hessian);
    double sum = 0;
    for (int j = 0; j < elements; ++j)
        sum += measure(gather<Dim, K>(x, points_of(j)));
    if (gradient)
        for (int j = 0; j < elements; ++j) {
            const std::array<int, K> points = points_of(j);
            const Eigen::Matrix<double, K * Dim, 1> local = gather<Dim, K>(x, points);
            scatter_gradient<Dim, K>(slope(local, measure(local)), points, k * (sum - rest), *gradient);
        }
    return harmonic_penalty(k, sum, rest);
}

// Parameters of eq. (9.1) for one particle, with uniform rest edge length and rest angle.
struct ShapeParameters
{
    double ka = 0;     // area stiffness k_a [E/L^4]
    double a0 = 0;     // preferred area a_0 [L^2]
    double kl = 0;     // edge stiffness k_l [E/L^2]
    double l0 = 0;     // preferred edge length l_0 [L]
    double kb = 0;     // bending stiffness k_b [E]
    double theta0 = 0; // preferred turning angle theta_0 [rad]
    double gamma = 0;  // line tension gamma [E/L]
};

// The terms of eq. (9.1), so that each can be evaluated and checked alone.
enum ShapeTerm : unsigned {
    area_term = 1u,
    edge_term = 2u,
    bending_term = 4u,
    line_tension_term = 8u,
    all_shape_terms = 15u
};

// Shape energy of the particle whose vertices are points first ... first + n - 1 of the flat array x
// (counter-clockwise, unwrapped: no periodic image inside a particle). Adds -(forces), i.e. the gradient,
// and the Hessian into `gradient` and `hessian` when they are given. `terms` selects terms of eq. (9.1).
double shape_energy(const ShapeParameters& shape, const Eigen::VectorXd& x, int first, int n,
                    Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms = all_shape_terms);

// Signed area of that particle's polygon.
double particle_area(const Eigen::VectorXd& x, int first, int n);
// Perimeter of that particle's polygon.
double particle_perimeter(const Eigen::VectorXd& x, int first, int n);

// Shape parameter A = p^2/(4 pi a) (section 9.3.1).
inline double shape_parameter(double perimeter, double area)
{
    return perimeter * perimeter / (4.0 * std::numbers::pi * area);
}

// Its minimum over N-gons, reached by the regular polygon: A_min = N tan(pi/N)/pi (section 9.3.1).
inline double minimum_shape_parameter(int n)
{
    return n * std::tan(std::numbers::pi / n) / std::numbers::pi;
}

// Circumradius of the regular N-gon of area a: a = N R^2 sin(2 pi/N)/2.
inline double regular_polygon_radius(int n, double area)
{
    return std::sqrt(2.0 * area / (n * std::sin(2.0 * std::numbers::pi / n)));
}

// The three particle types of Table 9.1.
enum class ShapeModel { floppy, shell, surface_tension };
std::string shape_model_name(ShapeModel model); // "floppy" | "shell" | "surface_tension"

// Parameters of Table 9.1 for a particle of n vertices, preferred area a0 and preferred shape parameter
// A0 >= A_min(n): l0 = sqrt(4 pi a0 A0)/n (so that (n l0)^2/(4 pi a0) = A0), theta0 = 2 pi/n.
//   floppy:          k_a, k_l > 0, k_b = 0, gamma = 0
//   shell:           k_a, k_l, k_b > 0, gamma = 0
//   surface_tension: k_a > 0, k_l = kl_surface (Table 9.1: ~0), k_b = 0, gamma > 0
struct ShapeStiffness
{
    double ka = 1, kl = 1, kb = 1, gamma = 0.1, kl_surface = 0;
};
ShapeParameters table_9_1_parameters(ShapeModel model, int n, double a0, double A0, const ShapeStiffness& k);

} // namespace softgrain::dpm
