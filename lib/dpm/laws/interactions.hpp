// Repulsion between deformable particles in 2D, DPM section 9.3.2.
//
// Rough (eqs. 9.3-9.4): every vertex is a disk of diameter sigma_mu; vertices of different particles repel
//   by U = k_c/2 (sigma_mb - r)^2 Theta(sigma_mb - r), sigma_mb = (sigma_mu + sigma_beta)/2; each pair once.
// Smooth (eqs. 9.5-9.9): vertex i of particle mu against the edges of particle beta,
//   U_int = 1/2 sum_mu sum_i sum_{beta != mu} sum_j (U^edge + U^concave + U^convex)_{mu i, beta j}
//   U^edge    (9.6) = k_c/2 (sigma_mb - d)^2 when 0 < d < sigma_mb and vertex i projects inside edge j
//                     (from vertex j-1 to vertex j); d = signed distance (9.7), positive outside beta;
//   U^concave (9.8) = -k_c/2 (sigma_mb - r)^2 when r = |r_i - r_j| < sigma_mb, vertex i projects inside
//                     edges j and j+1 (seen from vertex j) and lies outside both: removes the double counting
//                     of the two edge terms near a concave corner, so that forces are continuous;
//   U^convex  (9.9) = k_c/2 (sigma_mb - r)^2 when r < sigma_mb and vertex i lies beyond both edges at
//                     vertex j (the gap at a convex corner; the paper prints Theta(r - sigma_mb), the text
//                     and continuity give Theta(sigma_mb - r): decision dpm-eq99-heaviside).
//   The 1/2 of eq. (9.5) multiplies every ordered term as printed (decision dpm-smooth-half).
// Particles with one vertex are disks: they carry no edges (they interact through their vertex only).
// Sign: repulsive, U >= 0 (U^concave < 0 only cancels a doubly counted edge term); the functions add the
// gradient dU/dx = minus the forces. Units: energies [E], k_c [E/L^2], lengths [L]. The Hessian comes from
// local AutoDiff, and so does the gradient except that of the vertex springs when only the gradient is
// asked for (FIRE), which is analytic.
// The terms are found by one traversal, the system's vertex-level Verlet list (contact_list.hpp), which
// handles the periodic images and Lees-Edwards shear.
// Valid for particles whose vertices are counter-clockwise and unwrapped, and overlaps smaller than
// sigma_mb: a smooth vertex that has crossed an edge line (d <= 0) feels no edge term, so nothing pushes
// it back out. In a periodic box each pair interacts through one image only, so the box side must
// exceed twice the largest particle reach 2 R + sigma (R: largest vertex distance from the vertex mean;
// checked whenever the contact list is built), else NumericalError.
#pragma once

#include "dpm/laws/local_derivatives.hpp"

#include <Eigen/Core>

namespace softgrain::dpm {

struct DpmSystem;

// Terms of the smooth interaction, selectable for the continuity tests of Fig. 9.7.
enum SmoothTerm : unsigned { edge_smooth = 1u, concave_smooth = 2u, convex_smooth = 4u, all_smooth = 7u };

// Eq. (9.7) with the edge length as denominator (decision dpm-eq97-denominator): signed distance of the
// point p from the line through the edge a -> b, positive on the right of a -> b (outside a CCW polygon).
// x = (p, a, b).
template <class Scalar>
Scalar signed_edge_distance(const Eigen::Matrix<Scalar, 6, 1>& x)
{
    using std::sqrt;
    // z . (r_{b,a} x r_{b,p}) / |r_{b,a}|
    const Scalar bax = x(2) - x(4), bay = x(3) - x(5), bpx = x(0) - x(4), bpy = x(1) - x(5);
    return Scalar((bax * bpy - bay * bpx) / sqrt(bax * bax + bay * bay));
}

// Spring between two vertices in Dim dimensions, k/2 (sigma - r)^2 (eqs. 9.4, 9.8 with k < 0, 9.9);
// x = (r_1, r_2), r = |r_2 - r_1|. The caller applies the Heaviside factors. In 3D the vertices are spheres
// of diameter sigma (the rough interaction of section 9.3.2 carried over to 3D, system3d.hpp).
template <int Dim>
struct VertexSpring
{
    double k, sigma;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 2 * Dim, 1>& x) const
    {
        using std::sqrt;
        Scalar r2 = Scalar(0);
        for (int d = 0; d < Dim; ++d) {
            const Scalar delta = x(Dim + d) - x(d);
            r2 += delta * delta;
        }
        const Scalar overlap = Scalar(sigma) - Scalar(sqrt(r2));
        return Scalar(0.5 * k) * overlap * overlap;
    }
};
using VertexSpringEnergy = VertexSpring<2>;

// Vertex-edge spring k/2 (sigma - d)^2 of eq. (9.6); x = (p, a, b). The caller applies the Heavisides.
struct VertexEdgeEnergy
{
    double k, sigma;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 6, 1>& x) const
    {
        const Scalar overlap = Scalar(sigma) - signed_edge_distance(x);
        return Scalar(0.5 * k) * overlap * overlap;
    }
};

// Interaction energy of the system (rough or smooth, as system.interaction says); adds its gradient and
// Hessian when given. `smooth_terms` selects terms of the smooth interaction.
// `virial`, when given, accumulates the force moment sum r_a F_b of every interaction term at the
// coordinates it is evaluated with (minimum images): the pair part of eqs. (9.25)-(9.26) and its smooth
// analogue (section 9.4.2).
double interaction_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                          HessianSink hessian, unsigned smooth_terms = all_smooth,
                          Eigen::Matrix2d* virial = nullptr);

} // namespace softgrain::dpm
