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
// Each term is written once as a local function of the coordinates it depends on, templated on the
// scalar; forces and the exact Hessian come from local_derivatives.hpp. The area term is a penalty of a
// sum of local measures (shoelace terms); its derivatives follow by the chain rule from theirs. 3D shells
// (eq. 9.2) reuse harmonic_penalty, the local-term machinery and penalty_of_sum with a face volume.
#pragma once

#include "dpm/local_derivatives.hpp"

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

// Length of the edge between the two points of x = (x0, y0, x1, y1).
template <class Scalar>
Scalar edge_length(const Eigen::Matrix<Scalar, 4, 1>& x)
{
    using std::sqrt;
    const Scalar dx = x(2) - x(0), dy = x(3) - x(1);
    return Scalar(sqrt(dx * dx + dy * dy));
}

// Turning angle at the middle point of x = (previous, vertex, next): the signed angle from the incoming
// edge to the outgoing edge, in (-pi, pi]; positive where the polygon turns counter-clockwise.
template <class Scalar>
Scalar turning_angle(const Eigen::Matrix<Scalar, 6, 1>& x)
{
    using std::atan2;
    const Scalar ix = x(2) - x(0), iy = x(3) - x(1), ox = x(4) - x(2), oy = x(5) - x(3);
    const Scalar cross = ix * oy - iy * ox, dot = ix * ox + iy * oy;
    return Scalar(atan2(cross, dot));
}

// One shoelace term (x0 y1 - x1 y0)/2 of the polygon area; the sum over the edges is the signed area.
template <class Scalar>
Scalar shoelace_term(const Eigen::Matrix<Scalar, 4, 1>& x)
{
    return Scalar(0.5) * (x(0) * x(3) - x(2) * x(1));
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

// Edge-length penalty k_l/2 (l - l0)^2 of one edge (2 points).
struct EdgeLengthEnergy
{
    double kl, l0;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 4, 1>& x) const
    {
        return harmonic_penalty(kl, edge_length(x), l0);
    }
};

// Bending penalty k_b/2 (theta - theta0)^2 at one vertex (3 points).
struct BendingEnergy
{
    double kb, theta0;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 6, 1>& x) const
    {
        return harmonic_penalty(kb, turning_angle(x), theta0);
    }
};

// Line tension gamma l of one edge (2 points); summed over the edges it is gamma p.
struct LineTensionEnergy
{
    double gamma;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 4, 1>& x) const
    {
        return Scalar(gamma) * edge_length(x);
    }
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
ShapeModel shape_model_from_name(const std::string& name); // "floppy" | "shell" | "surface_tension"

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
