// Reference Voronoi cells of VSM (Frenning 2022, section 2.1) and the gradient vectors B_ab (section 2.2).
//
// The domain D is bounded by planar faces; here every face is an axis-aligned rectangle (boxes and unions of
// boxes such as the L-shaped block). Each real particle a near a face gets a ghost b mirrored across it:
// W_ab = closest point of X_a on the face, X_b = 2 W_ab - X_a (section 2.1). The Voronoi diagram of particles
// and ghosts (voro++) then reproduces the flat boundary exactly. The method is total Lagrangian: all of this
// is computed once, in the reference configuration. Units: lengths in m, areas in m^2, volumes in m^3.
//
// A domain may also be cut by a sphere |X| < R (the ball of compare.solid). Section 2.1 extends the ghosts to
// such a boundary ("can be extended to complex geometries"): the closest point of X_a on the sphere is
// W_ab = R X_a/|X_a|, and the ghost X_b = 2 W_ab - X_a is the mirror across the tangent plane there. Each
// particle's cell is cut by its own tangent plane only (voro++'s spherical wall does exactly this cut), so a
// cell never meets another particle's spherical ghost; the cells then cover the ball and exceed it by the
// slivers between the tangent facets and the sphere, O((spacing/R)^2) of its volume (decision
// vsm-ball-ghosts).
#pragma once

#include "core/vector.hpp"

#include <utility>
#include <vector>

namespace softgrain::vsm {

// One planar face of the domain boundary: the rectangle low <= X <= high in the plane X[axis] = position
// (low[axis] = high[axis] = position), with outward unit normal outward * e_axis. `label` groups faces that
// share a boundary condition.
struct BoundaryFace
{
    int axis = 0;
    double position = 0;
    double outward = 1;
    Vec3 low = Vec3::Zero(), high = Vec3::Zero();
    int label = 0;
    Vec3 normal() const { return outward * Vec3::Unit(axis); }
};

// A union of (possibly overlapping) boxes bounded by the listed faces, optionally cut by the sphere
// |X| < sphere_radius (centre at the origin).
struct Domain
{
    std::vector<BoundaryFace> faces;
    std::vector<std::pair<Vec3, Vec3>> boxes; // (low, high): a point is inside when strictly inside one box
    Vec3 low = Vec3::Zero(), high = Vec3::Zero(); // bounding box
    double volume = 0;
    double sphere_radius = 0; // > 0: the domain is also inside this sphere, whose surface has sphere_label
    int sphere_label = -1;
};

// The box low <= X <= high; face labels 0..5 are -X1, +X1, -X2, +X2, -X3, +X3.
Domain box_domain(const Vec3& low, const Vec3& high);

// The L-shaped block: union of [0,a]x[0,t]x[0,t] and [0,t]x[0,b]x[0,t] (t < a, t < b). Face labels: 0 the
// face X1 = a, 1 the face X2 = b, 2 every other face.
Domain l_block_domain(double a, double b, double t);

// The octant X1, X2, X3 >= 0 of the ball |X| < R. Labels: 0, 1, 2 the planes X1 = 0, X2 = 0, X3 = 0; 3 the
// spherical surface.
Domain ball_octant_domain(double R);

// A Voronoi face of real particle a, shared with neighbour b (a real particle or a ghost).
struct Neighbour
{
    int particle = -1;          // index of the real neighbour b, or -1 for a ghost
    int face = -1;              // ghost: index into Domain::faces of the mirror face; -1 for a real neighbour
                                // or a ghost across the sphere
    int label = -1;             // ghost: boundary-condition label of its face (or of the sphere)
    int reverse = -1;           // real neighbour: position of a in the neighbour list of b
    Vec3 branch = Vec3::Zero(); // X_ab = X_b - X_a
    double length = 0;          // L_ab = |X_ab|
    double area = 0;            // A_ab, face area
    Vec3 normal = Vec3::Zero(); // N_ab = X_ab / L_ab, outward from a
    Vec3 centroid = Vec3::Zero();       // C_ab, eq. (2)
    Vec3 B_ab = Vec3::Zero();           // eq. (7)
    Vec3 B_ba = Vec3::Zero();           // eq. (7) with a and b exchanged: (A_ab / L_ab)(C_ab - X_b)
    Vec3 boundary_point = Vec3::Zero(); // ghost: W_ab = (X_a + X_b)/2 on the boundary face
    bool ghost() const { return particle < 0; }
};

struct ReferenceCells
{
    Points<3> X;                                    // reference positions of the real particles
    std::vector<double> volume;                     // V_a
    std::vector<std::vector<Neighbour>> neighbours; // P'_a: real neighbours I'_a and ghosts E_a
    std::vector<Vec3> B_self;                       // B_aa, eq. (9)
    int ghost_count = 0;                            // distinct ghost points used
    std::size_t size() const { return volume.size(); }
};

// B_ab = (1/L_ab) int_{dV_ab} (X - X_a) dA = (A_ab / L_ab)(C_ab - X_a), eq. (7). Units: m^2.
inline Vec3 gradient_vector(double area, double length, const Vec3& centroid, const Vec3& X_a)
{
    return (area / length) * (centroid - X_a);
}

// Builds the reference cells of the particles X inside `domain`. Particles closer than mirror_distance to a
// boundary face (and projecting onto it) get a ghost; mirror_distance must exceed the largest cell radius
// (about 2 particle spacings is ample). Throws InputError when a particle lies outside the domain, when two
// particles coincide, or when the cells do not tile the domain (sum V_a != |D|, mirror_distance too small;
// with a sphere: the cells do not cover the domain, or exceed it by more than the slivers under their
// spherical facets).
ReferenceCells build_reference_cells(const Points<3>& X, const Domain& domain, double mirror_distance);

} // namespace softgrain::vsm
