// Smooth repulsion between 3D deformable particles, DPM section 9.3.2 in 3D (Fig. 9.6d): the surface of
// particle beta is a sphero-polyhedron, its triangulated mesh swept by a sphere of diameter sigma_beta, and
// a vertex sphere of particle mu overlaps it where its distance d from the mesh is below
// sigma_mb = (sigma_mu + sigma_beta)/2; the repulsion is k_c/2 (sigma_mb - d)^2 (eq. 9.6 with the distance
// to a face instead of an edge).
//
// Double counting (decision dpm-3d-smooth-inclusion-exclusion): the distance to the mesh is the distance
// to its nearest face, edge or vertex. Near an edge or a vertex several closed triangles share the nearest
// point, and at a concave edge two faces are near at once (the 2D concave corner of eq. 9.8). Vertex i of
// mu therefore sees particle beta through the Euler-type sum over the mesh's closed cells
//
//   U_i,beta = sum_faces U(d_if) - sum_edges U(d_ie) + sum_vertices U(r_ij),  U(d) = k/2 (sigma_mb - d)^2,
//
// each term with Theta(sigma_mb - d), d_if the distance to the closed triangle f (face interior, edges and
// corners: point_triangle_distance), d_ie to the closed segment e, r_ij to vertex j. Where the nearest
// point of the mesh lies inside a face, on an edge or at a vertex of a convex part of the mesh, all other
// terms cancel in pairs (identical functions of the same vertices) and U_i,beta = U(distance to the mesh);
// at a concave edge the two faces count and the edge term is subtracted where the point sees both, which
// makes the forces continuous. In 2D the same sum over edges and vertices is exactly
// eqs. (9.6) + (9.8) + (9.9). On a planar patch of the mesh U_i,beta = U(height above the plane) wherever
// the point lies.
//
// Both ways (decision dpm-3d-smooth-both-ways): every vertex of mu against the surface of beta and every
// vertex of beta against the surface of mu, each ordered term with the factor 1/2 of eq. (9.5) as in 2D
// (decision dpm-smooth-half). No edge-edge term: two edges that cross with no vertex within sigma_mb of the
// other surface are not seen (contacts are between a vertex and a surface, as in the paper).
//
// Sign: repulsive (U(d) >= 0; the subtracted edge terms only cancel doubly counted faces); the functions
// add the gradient dU/dx = minus the forces.
// Valid for a vertex outside particle beta. A vertex that has passed through a face (it lies on
// the inner side of the face whose interior holds its nearest point, closer than sigma_mb) is reported as
// a NumericalError; the mesh must have no spikes sharper than 90 degrees within sigma_mb of the vertex
// (there an unsigned distance would also see the far side).
// Energies [E], k_c [E/L^2], lengths [L]. Gradients and Hessians by local AutoDiff (local_derivatives.hpp).
#pragma once

#include "dpm/laws/local_derivatives.hpp"
#include "dpm/system/mesh3d.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

namespace softgrain::dpm {

struct DpmSystem3d;

// The part of a closed triangle (a, b, c) that holds the point nearest to p: one of its seven Voronoi
// regions (Ericson, Real-Time Collision Detection, sec. 5.1.5). Boundaries between regions go to the
// lower-dimensional feature; the distance is continuous across them.
enum class TriangleFeature { face, edge_ab, edge_bc, edge_ca, vertex_a, vertex_b, vertex_c };
TriangleFeature nearest_triangle_feature(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                         const Eigen::Vector3d& b, const Eigen::Vector3d& c);

namespace detail {

template <class Scalar>
using Point3 = Eigen::Matrix<Scalar, 3, 1>;

inline double value_of(double v)
{
    return v;
}
template <class Derivatives>
double value_of(const Eigen::AutoDiffScalar<Derivatives>& v)
{
    return value_of(v.value());
}
template <class Scalar>
Eigen::Vector3d values(const Point3<Scalar>& p)
{
    return {value_of(p(0)), value_of(p(1)), value_of(p(2))};
}

template <class Scalar>
Scalar distance(const Point3<Scalar>& p, const Point3<Scalar>& q)
{
    using std::sqrt;
    const Point3<Scalar> d = p - q;
    return Scalar(sqrt(d.squaredNorm()));
}

// Distance from p to the line through a and b: |(p - a) x (b - a)| / |b - a|.
template <class Scalar>
Scalar line_distance(const Point3<Scalar>& p, const Point3<Scalar>& a, const Point3<Scalar>& b)
{
    using std::sqrt;
    const Point3<Scalar> ab = b - a, ap = p - a;
    const Point3<Scalar> n = ap.cross(ab);
    return Scalar(sqrt(n.squaredNorm() / ab.squaredNorm()));
}

} // namespace detail

// Distance from p to the closed segment [a, b]; x = (p, a, b).
template <class Scalar>
Scalar point_segment_distance(const Eigen::Matrix<Scalar, 9, 1>& x)
{
    using detail::Point3;
    const Point3<Scalar> p = x.template segment<3>(0), a = x.template segment<3>(3),
                         b = x.template segment<3>(6);
    const Eigen::Vector3d pv = detail::values(p), av = detail::values(a), bv = detail::values(b);
    if ((pv - av).dot(bv - av) <= 0) return detail::distance(p, a);
    if ((pv - bv).dot(av - bv) <= 0) return detail::distance(p, b);
    return detail::line_distance(p, a, b);
}

// Distance from p to the closed triangle (a, b, c): to its plane (face interior), to the line of an edge
// or to a corner, as nearest_triangle_feature says; x = (p, a, b, c).
template <class Scalar>
Scalar point_triangle_distance(const Eigen::Matrix<Scalar, 12, 1>& x)
{
    using detail::Point3;
    using std::sqrt;
    const Point3<Scalar> p = x.template segment<3>(0), a = x.template segment<3>(3),
                         b = x.template segment<3>(6), c = x.template segment<3>(9);
    switch (nearest_triangle_feature(detail::values(p), detail::values(a), detail::values(b),
                                     detail::values(c))) {
    case TriangleFeature::face: {
        const Point3<Scalar> n = (b - a).cross(c - a);
        const Scalar height = (p - a).dot(n);
        return Scalar(sqrt(height * height / n.squaredNorm()));
    }
    case TriangleFeature::edge_ab:
        return detail::line_distance(p, a, b);
    case TriangleFeature::edge_bc:
        return detail::line_distance(p, b, c);
    case TriangleFeature::edge_ca:
        return detail::line_distance(p, c, a);
    case TriangleFeature::vertex_a:
        return detail::distance(p, a);
    case TriangleFeature::vertex_b:
        return detail::distance(p, b);
    case TriangleFeature::vertex_c:
        break;
    }
    return detail::distance(p, c);
}

// k/2 (sigma - d)^2 with d the distance from a point to a closed triangle (K = 4 points) or segment
// (K = 3); the caller applies Theta(sigma - d) and the sign of the inclusion-exclusion (k < 0).
struct PointTriangleSpring
{
    double k, sigma;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 12, 1>& x) const
    {
        const Scalar overlap = Scalar(sigma) - point_triangle_distance(x);
        return Scalar(0.5 * k) * overlap * overlap;
    }
};
struct PointSegmentSpring
{
    double k, sigma;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 9, 1>& x) const
    {
        const Scalar overlap = Scalar(sigma) - point_segment_distance(x);
        return Scalar(0.5 * k) * overlap * overlap;
    }
};

// Smooth interaction energy of a 3D system (the sum above over every ordered pair of different particles,
// both ways, with the factor 1/2), in open space or the periodic box (Lees-Edwards sheared or not):
// particle beta is taken at every periodic image within reach of a vertex of mu (several in a small box),
// the terms found by the system's vertex list (vertex_pairs3d.hpp) and summed per ordered pair. Adds
// the gradient and Hessian when given; `virial` accumulates the force moment sum_k y_k F_k^T of every term at
// its imaged coordinates (the smooth analogue of the pair part of eq. 9.26, as eq. 9.26's text says for 2D).
double smooth_interaction_energy3d(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                   Eigen::VectorXd* gradient, HessianSink hessian,
                                   Eigen::Matrix3d* virial = nullptr);

// One ordered half of the above: every vertex of particle mu against the surface of particle beta (with
// the 1/2 of eq. 9.5), all images; the value only.
double smooth_vertex_surface_energy3d(const DpmSystem3d& system, int mu, int beta, const Eigen::VectorXd& x);

// Number of vertices of each particle closer than sigma_mb to the mesh of another particle, plus the
// number of its own mesh's vertex-surface contacts with the vertices of others (each contact counted for
// both particles, as contact_counts3d does for vertex pairs).
std::vector<int> smooth_contact_counts3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

// The smooth contacts as (vertex i, particle beta): i within sigma_mb of an image of beta's surface, in the
// order of smooth_contact_counts3d (one entry per image touched).
std::vector<std::pair<int, int>> smooth_touching_pairs3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
