// Closed triangulated surfaces of 3D deformable particles, DPM section 9.3.1: N vertices, N_f triangular
// faces and N_e edges with N + N_f - N_e = 2 (Euler) and 2 N_e = 3 N_f, hence N_f = 2N - 4, N_e = 3N - 6.
//
// Meshes: the regular tetrahedron, octahedron and icosahedron, and geodesic icosahedra (each face of the
// icosahedron split into 4 at its edge midpoints, s times, every vertex projected to the sphere:
// N = 10 * 4^s + 2 = 12, 42, 162, 642). Vertices lie on the sphere of radius 1 about the origin.
// Faces are oriented counter-clockwise seen from outside (outward normal (r1 - r0) x (r2 - r0)).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

namespace softgrain::dpm {

// One edge (a, b) and the two faces sharing it: face (a, b, c) and face (b, a, d), both as oriented in
// the mesh; c and d are the vertices opposite the edge. The dihedral (bending) angle of eq. (9.2) is a
// function of the four points (a, b, c, d).
struct MeshEdge
{
    int a = 0, b = 0, c = 0, d = 0;
};

struct TriangleMesh
{
    Eigen::Matrix3Xd vertices;             // 3 x N
    std::vector<std::array<int, 3>> faces; // N_f, counter-clockwise seen from outside
    std::vector<MeshEdge> edges;           // N_e, built from the faces by build_edges

    int vertex_count() const { return static_cast<int>(vertices.cols()); }
    int face_count() const { return static_cast<int>(faces.size()); }
    int edge_count() const { return static_cast<int>(edges.size()); }
};

// Fills mesh.edges from mesh.faces; throws NumericalError unless every edge is shared by exactly two
// faces with opposite orientations (a closed, consistently oriented 2-manifold).
void build_edges(TriangleMesh& mesh);

TriangleMesh tetrahedron_mesh();
TriangleMesh octahedron_mesh();
TriangleMesh icosahedron_mesh();
// The icosahedron subdivided `subdivisions` times (4 triangles per triangle) and projected to the sphere.
TriangleMesh geodesic_icosahedron(int subdivisions);

// A flat closed box (test and figure target for contacts on a plane): the top face z = thickness/2 and
// the bottom face z = -thickness/2 are square grids of n x n vertices `spacing` apart, centred on the z
// axis, each grid square split along its (+x, +y) diagonal; the four sides are strips of one row of
// squares between the top and bottom rims. Not on the unit sphere. n >= 2.
TriangleMesh slab_mesh(int n, double spacing, double thickness);

// `mesh` rotated about its centre so that vertex 0 points down (-z): a probe or slider whose lowest point
// is that vertex, pressed on or slid over a slab.
TriangleMesh vertex_down(TriangleMesh mesh);

// "tetrahedron" | "octahedron" | "icosahedron" | "geodesic42" | "geodesic162" | "geodesic642" |
// "geodesic2562" (the mesh choice of dpm.shape3d); throws InputError otherwise.
TriangleMesh mesh_from_name(const std::string& name);

// The `mesh` choice of dpm.shape3d, dpm.modes3d and dpm.shear_modulus3d: every mesh_from_name knows but
// geodesic2562.
std::vector<std::string> particle_mesh_names();

} // namespace softgrain::dpm
