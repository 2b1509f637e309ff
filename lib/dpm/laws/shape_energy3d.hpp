// Shape energy of a 3D deformable particle, DPM eq. (9.2):
//
//   U = k_v/2 (v - v0)^2 + sum_f k_a/2 (a_f - a_f0)^2 + sum_e k_b/2 (theta_e - theta_e0)^2 + gamma s
//
// v: volume enclosed by the triangulated surface (sum over faces of the signed volume r0 . (r1 x r2)/6 of
// the tetrahedron (origin, face), exact for a closed outward-oriented surface); a_f: area of face f;
// theta_e: bending angle at edge e, the signed angle between the outward normals of the two faces sharing
// it (0 for a flat surface, positive where the surface is convex); s = sum_f a_f (surface tension gamma).
// Units: lengths [L], k_v [E/L^6], k_a [E/L^4], k_b [E], gamma [E/L^2].
// Sign: U >= 0 for k_v, k_a, k_b, gamma >= 0; v > 0 and theta_e > 0 at convex edges for an
// outward-oriented mesh; shape_energy3d adds the gradient dU/dx = minus the forces.
// Valid for a closed, outward-oriented (mesh3d.hpp), unwrapped surface that does not intersect itself,
// with non-degenerate faces (the gradients of a_f and theta_e are undefined for a degenerate triangle)
// and bending angles away from +-pi, where theta_e jumps by 2 pi (a face folded onto its neighbour).
//
// Each term is written once as a local function of the coordinates of its points, templated on the
// scalar; the exact Hessian follows from local_derivatives.hpp (as in 2D, shape_energy.hpp), and so do the
// forces when the Hessian is asked for too; forces alone (FIRE) use the analytic local gradients below.
// The volume term is a penalty of a sum of local measures; its derivatives follow by the chain rule.
#pragma once

#include "dpm/laws/local_derivatives.hpp"
#include "dpm/laws/shape_energy.hpp"
#include "dpm/system/mesh3d.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace softgrain::dpm {

// The local measures of eq. (9.2), named generic callables as those of eq. (9.1) (shape_energy.hpp).

// Signed volume r0 . (r1 x r2)/6 of the tetrahedron (origin, r0, r1, r2), x = (r0, r1, r2).
inline constexpr auto face_volume = []<class Scalar>(const Eigen::Matrix<Scalar, 9, 1>& x) -> Scalar {
    const Eigen::Matrix<Scalar, 3, 1> r0 = x.template segment<3>(0), r1 = x.template segment<3>(3),
                                      r2 = x.template segment<3>(6);
    const Eigen::Matrix<Scalar, 3, 1> c = r1.cross(r2);
    return Scalar(r0.dot(c) / 6.0);
};

// Area |(r1 - r0) x (r2 - r0)|/2 of the triangle x = (r0, r1, r2).
inline constexpr auto triangle_area = []<class Scalar>(const Eigen::Matrix<Scalar, 9, 1>& x) -> Scalar {
    using std::sqrt;
    const Eigen::Matrix<Scalar, 3, 1> u = x.template segment<3>(3) - x.template segment<3>(0),
                                      w = x.template segment<3>(6) - x.template segment<3>(0);
    const Eigen::Matrix<Scalar, 3, 1> n = u.cross(w);
    return Scalar(0.5 * sqrt(n.squaredNorm()));
};

// Bending angle at the edge (a, b) of x = (a, b, c, d) shared by the faces (a, b, c) and (b, a, d):
// theta = atan2(e . (n1 x n2)/|e|, n1 . n2) with e = b - a and the face normals n1 = (b - a) x (c - a),
// n2 = (a - b) x (d - b); in (-pi, pi], positive for a convex (outward-bent) edge, smooth through 0.
inline constexpr auto dihedral_angle = []<class Scalar>(const Eigen::Matrix<Scalar, 12, 1>& x) -> Scalar {
    using std::atan2;
    using std::sqrt;
    const Eigen::Matrix<Scalar, 3, 1> a = x.template segment<3>(0), b = x.template segment<3>(3),
                                      c = x.template segment<3>(6), d = x.template segment<3>(9);
    const Eigen::Matrix<Scalar, 3, 1> e = b - a;
    const Eigen::Matrix<Scalar, 3, 1> n1 = e.cross(c - a);
    const Eigen::Matrix<Scalar, 3, 1> n2 = (a - b).cross(d - b);
    const Eigen::Matrix<Scalar, 3, 1> m = n1.cross(n2);
    const Scalar sine = e.dot(m) / sqrt(e.squaredNorm());
    const Scalar cosine = n1.dot(n2);
    return Scalar(atan2(sine, cosine));
};

// Analytic first derivatives ("slopes") of the three local measures above, generic in the scalar as in 2D
// (shape_energy.hpp): in double the gradient-only path (FIRE; the AutoDiff gradient of the same measures
// costs several times more, decision dpm-3d-analytic-gradient), in first-order AutoDiff the measures'
// Hessian. Verified against the AutoDiff gradients and Hessians to round-off and against finite
// differences (verification/dpm/laws/shape_energy3d.cpp).
//   grad face_volume  = (r1 x r2, r2 x r0, r0 x r1)/6;
//   grad triangle_area: with the unit normal m = n/|n|,
//     d a/d r1 = (r2 - r0) x m/2, d a/d r2 = m x (r1 - r0)/2,
//     d a/d r0 = -(d a/d r1 + d a/d r2) (translation invariance); undefined for a degenerate triangle;
//   grad dihedral_angle: the opposite points move theta only by turning their face about the edge,
//     d theta/d c = -|e| n1/|n1|^2, d theta/d d = -|e| n2/|n2|^2 (minus: lifting c along its face's outward
//     normal flattens a convex edge); the edge points carry the rest according to where c and d project on
//     the edge, with t_c = (c - a) . e/|e|^2: d theta/d b = -(t_c d theta/d c + t_d d theta/d d),
//     d theta/d a = -(d theta/d b + d theta/d c + d theta/d d); undefined for a degenerate face.
// Their forward-mode Jacobian (local_hessian_from_slope) costs a fifteenth of nested AutoDiff of the angle
// itself, which took 80 % of a 3D packing's Hessian assembly.
inline constexpr auto face_volume_slope = []<class Scalar>(const Eigen::Matrix<Scalar, 9, 1>& x,
                                                           const Scalar&) -> Eigen::Matrix<Scalar, 9, 1> {
    using Vector = Eigen::Matrix<Scalar, 3, 1>;
    const Vector r0 = x.template segment<3>(0), r1 = x.template segment<3>(3), r2 = x.template segment<3>(6);
    const Scalar six(6.0);
    Eigen::Matrix<Scalar, 9, 1> g;
    g << r1.cross(r2) / six, r2.cross(r0) / six, r0.cross(r1) / six;
    return g;
};

inline constexpr auto triangle_area_slope =
    []<class Scalar>(const Eigen::Matrix<Scalar, 9, 1>& x,
                     const Scalar& area) -> Eigen::Matrix<Scalar, 9, 1> {
    using Vector = Eigen::Matrix<Scalar, 3, 1>;
    const Vector r0 = x.template segment<3>(0), r1 = x.template segment<3>(3), r2 = x.template segment<3>(6);
    const Vector n = (r1 - r0).cross(r2 - r0);
    const Scalar length = Scalar(2.0) * area; // |n|
    const Vector m = n / length;
    const Vector g1 = Scalar(0.5) * (r2 - r0).cross(m), g2 = Scalar(0.5) * m.cross(r1 - r0);
    Eigen::Matrix<Scalar, 9, 1> g;
    g << -(g1 + g2), g1, g2;
    return g;
};

inline constexpr auto dihedral_angle_slope = []<class Scalar>(const Eigen::Matrix<Scalar, 12, 1>& x,
                                                              const Scalar&) -> Eigen::Matrix<Scalar, 12, 1> {
    using std::sqrt;
    using Vector = Eigen::Matrix<Scalar, 3, 1>;
    const Vector a = x.template segment<3>(0), b = x.template segment<3>(3), c = x.template segment<3>(6),
                 d = x.template segment<3>(9);
    const Vector e = b - a;
    const Vector n1 = e.cross(c - a), n2 = (a - b).cross(d - b);
    const Scalar e2 = e.squaredNorm();
    const Scalar length = sqrt(e2);
    const Scalar wc = -length / n1.squaredNorm(), wd = -length / n2.squaredNorm();
    const Vector gc = wc * n1, gd = wd * n2;
    const Scalar tc = (c - a).dot(e) / e2, td = (d - a).dot(e) / e2;
    const Vector gb = -(tc * gc + td * gd);
    Eigen::Matrix<Scalar, 12, 1> g;
    g << -(gb + gc + gd), gb, gc, gd;
    return g;
};

// Parameters of eq. (9.2) for one particle: per-face rest areas and per-edge rest angles (in the order of
// the mesh's faces and edges), since on a geodesic mesh they are not uniform (section 9.3.1).
struct ShapeParameters3d
{
    double kv = 0;              // volume stiffness k_v [E/L^6]
    double v0 = 0;              // preferred volume v_0 [L^3]
    double ka = 0;              // face-area stiffness k_a [E/L^4]
    std::vector<double> a0;     // preferred face areas a_f0 [L^2]
    double kb = 0;              // bending stiffness k_b [E]
    std::vector<double> theta0; // preferred bending angles theta_e0 [rad]
    double gamma = 0;           // surface tension gamma [E/L^2]
};

enum ShapeTerm3d : unsigned {
    volume_term3d = 1u,
    face_area_term3d = 2u,
    bending_term3d = 4u,
    surface_tension_term3d = 8u,
    all_shape_terms3d = 15u
};

// Shape energy eq. (9.2) of the particle with the mesh's connectivity whose vertex v is point first + v of
// the flat array x (point p at x(3p) ... x(3p + 2)). Adds the gradient (= -forces) and the Hessian when
// given (the gradient alone from the analytic local gradients, with the Hessian from AutoDiff); `terms`
// selects terms of eq. (9.2).
double shape_energy3d(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                      int first, Eigen::VectorXd* gradient, HessianSink hessian,
                      unsigned terms = all_shape_terms3d);

// Geometric measures of that particle at x.
double mesh_volume(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first);
double mesh_surface_area(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first);
std::vector<double> mesh_face_areas(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first);
std::vector<double> mesh_bending_angles(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first);

// The mesh's vertices as a flat array (3N).
Eigen::VectorXd mesh_coordinates(const TriangleMesh& mesh);

// 3D shape parameter A^3D = s^(3/2)/(6 sqrt(pi) v) (section 9.3.1); 1 for a sphere.
inline double shape_parameter3d(double surface, double volume)
{
    return std::pow(surface, 1.5) / (6.0 * std::sqrt(std::numbers::pi) * volume);
}
// A^3D of the particle at x (mesh_coordinates(mesh): the undeformed mesh, A_min^3D of the text).
inline double mesh_shape_parameter3d(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first)
{
    return shape_parameter3d(mesh_surface_area(mesh, x, first), mesh_volume(mesh, x, first));
}

// Rest state taken from the mesh's own geometry at x: v0 = its volume, a_f0 = area_scale * its face areas,
// theta_e0 = its bending angles; the stiffnesses as given. With area_scale = 1 the mesh has zero energy
// apart from gamma s; with area_scale = c the preferred shape parameter A0 is c^(3/2) times the mesh's.
ShapeParameters3d rest_shape_from_mesh(const TriangleMesh& mesh, const Eigen::VectorXd& x, double kv,
                                       double ka, double kb, double gamma, double area_scale = 1.0);

} // namespace softgrain::dpm
