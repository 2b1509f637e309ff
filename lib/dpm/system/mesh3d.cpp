#include "dpm/system/mesh3d.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace softgrain::dpm {

namespace {

// Orients every face counter-clockwise seen from outside, for a mesh star-shaped about the origin (all
// meshes here): the outward normal points away from the origin.
void orient_outward(TriangleMesh& mesh)
{
    for (auto& f : mesh.faces) {
        const Eigen::Vector3d r0 = mesh.vertices.col(f[0]), r1 = mesh.vertices.col(f[1]),
                              r2 = mesh.vertices.col(f[2]);
        if ((r1 - r0).cross(r2 - r0).dot(r0 + r1 + r2) < 0) std::swap(f[1], f[2]);
    }
}

// Normalised vertices, faces oriented, edges built.
TriangleMesh make_mesh(Eigen::Matrix3Xd vertices, std::vector<std::array<int, 3>> faces)
{
    TriangleMesh mesh;
    vertices.colwise().normalize();
    mesh.vertices = std::move(vertices);
    mesh.faces = std::move(faces);
    orient_outward(mesh);
    build_edges(mesh);
    return mesh;
}

} // namespace

void build_edges(TriangleMesh& mesh)
{
    // Directed edge (a, b) of a face -> the face's third vertex.
    std::map<std::pair<int, int>, int> opposite;
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const bool fresh = opposite.emplace(std::make_pair(f[k], f[(k + 1) % 3]), f[(k + 2) % 3]).second;
            if (!fresh)
                throw NumericalError("mesh edge orientation", 0,
                                     "two faces traverse an edge in the same direction (inconsistent mesh)");
        }
    mesh.edges.clear();
    for (const auto& [directed, c] : opposite) {
        const auto [a, b] = directed;
        if (a > b) continue; // each undirected edge once, from its (a < b) direction
        const auto twin = opposite.find({b, a});
        if (twin == opposite.end())
            throw NumericalError("mesh edge " + std::to_string(a) + "-" + std::to_string(b), 0,
                                 "an edge with a single face: the surface is not closed");
        mesh.edges.push_back({a, b, c, twin->second});
    }
}

TriangleMesh tetrahedron_mesh()
{
    Eigen::Matrix3Xd v(3, 4);
    v << 1, 1, -1, -1, //
        1, -1, 1, -1,  //
        1, -1, -1, 1;
    return make_mesh(v, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
}

TriangleMesh octahedron_mesh()
{
    Eigen::Matrix3Xd v(3, 6);
    v << 1, -1, 0, 0, 0, 0, //
        0, 0, 1, -1, 0, 0,  //
        0, 0, 0, 0, 1, -1;
    std::vector<std::array<int, 3>> faces;
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5})
                faces.push_back({x, y, z});
    return make_mesh(v, faces);
}

TriangleMesh icosahedron_mesh()
{
    // The 12 vertices (0, +-1, +-phi) and their cyclic permutations; the 20 faces are the triples of
    // mutually adjacent vertices (distance 2, the edge length).
    const double phi = (1 + std::sqrt(5.0)) / 2;
    Eigen::Matrix3Xd v(3, 12);
    int n = 0;
    for (double s : {-1.0, 1.0})
        for (double t : {-phi, phi}) {
            v.col(n++) = Eigen::Vector3d(0, s, t);
            v.col(n++) = Eigen::Vector3d(s, t, 0);
            v.col(n++) = Eigen::Vector3d(t, 0, s);
        }
    const auto adjacent = [&v](int i, int j) { return std::abs((v.col(i) - v.col(j)).norm() - 2) < 1e-9; };
    std::vector<std::array<int, 3>> faces;
    for (int i = 0; i < 12; ++i)
        for (int j = i + 1; j < 12; ++j)
            for (int k = j + 1; k < 12; ++k)
                if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) faces.push_back({i, j, k});
    return make_mesh(v, faces);
}

TriangleMesh geodesic_icosahedron(int subdivisions)
{
    if (subdivisions < 0)
        throw InputError("subdivisions = " + std::to_string(subdivisions) + ": must be >= 0");
    TriangleMesh mesh = icosahedron_mesh();
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<Eigen::Vector3d> points(mesh.vertices.colwise().begin(), mesh.vertices.colwise().end());
        std::map<std::pair<int, int>, int> midpoint;
        const auto middle = [&](int i, int j) {
            const auto key = std::minmax(i, j);
            const auto [it, fresh] = midpoint.emplace(key, static_cast<int>(points.size()));
            if (fresh) points.push_back((points[i] + points[j]).normalized());
            return it->second;
        };
        std::vector<std::array<int, 3>> faces;
        for (const auto& f : mesh.faces) {
            const int m01 = middle(f[0], f[1]), m12 = middle(f[1], f[2]), m20 = middle(f[2], f[0]);
            faces.push_back({f[0], m01, m20});
            faces.push_back({f[1], m12, m01});
            faces.push_back({f[2], m20, m12});
            faces.push_back({m01, m12, m20});
        }
        Eigen::Matrix3Xd v(3, static_cast<Eigen::Index>(points.size()));
        for (std::size_t i = 0; i < points.size(); ++i)
            v.col(static_cast<Eigen::Index>(i)) = points[i];
        mesh = make_mesh(v, faces);
    }
    return mesh;
}

TriangleMesh vertex_down(TriangleMesh mesh)
{
    mesh.vertices = Eigen::Quaterniond::FromTwoVectors(mesh.vertices.col(0), -Eigen::Vector3d::UnitZ())
                        .toRotationMatrix() *
                    mesh.vertices;
    return mesh;
}

TriangleMesh slab_mesh(int n, double spacing, double thickness)
{
    if (n < 2) throw InputError("slab grid n = " + std::to_string(n) + ": allowed n >= 2");
    Eigen::Matrix3Xd vertices(3, 2 * n * n);
    const auto index = [n](int layer, int i, int j) { return layer * n * n + j * n + i; };
    const double half = 0.5 * (n - 1) * spacing;
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                vertices.col(index(layer, i, j)) << i * spacing - half, j * spacing - half,
                    (layer == 0 ? 0.5 : -0.5) * thickness;
    std::vector<std::array<int, 3>> faces;
    const auto quad = [&faces](int a, int b, int c, int d) { // a-b-c-d around, split along a-c
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
    };
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j + 1 < n; ++j)
            for (int i = 0; i + 1 < n; ++i)
                quad(index(layer, i, j), index(layer, i + 1, j), index(layer, i + 1, j + 1),
                     index(layer, i, j + 1));
    // The rim of the grid once around, then one side square per rim step.
    std::vector<std::pair<int, int>> rim;
    for (int i = 0; i + 1 < n; ++i)
        rim.push_back({i, 0});
    for (int j = 0; j + 1 < n; ++j)
        rim.push_back({n - 1, j});
    for (int i = n - 1; i > 0; --i)
        rim.push_back({i, n - 1});
    for (int j = n - 1; j > 0; --j)
        rim.push_back({0, j});
    for (std::size_t k = 0; k < rim.size(); ++k) {
        const auto [i0, j0] = rim[k];
        const auto [i1, j1] = rim[(k + 1) % rim.size()];
        quad(index(0, i0, j0), index(0, i1, j1), index(1, i1, j1), index(1, i0, j0));
    }
    TriangleMesh mesh; // not make_mesh: the vertices stay where they are
    mesh.vertices = vertices;
    mesh.faces = faces;
    orient_outward(mesh); // convex about the origin
    build_edges(mesh);
    return mesh;
}

TriangleMesh mesh_from_name(const std::string& name)
{
    if (name == "tetrahedron") return tetrahedron_mesh();
    if (name == "octahedron") return octahedron_mesh();
    if (name == "icosahedron") return icosahedron_mesh();
    if (name == "geodesic42") return geodesic_icosahedron(1);
    if (name == "geodesic162") return geodesic_icosahedron(2);
    if (name == "geodesic642") return geodesic_icosahedron(3);
    if (name == "geodesic2562") return geodesic_icosahedron(4);
    throw InputError("mesh = '" + name +
                     "': allowed tetrahedron | octahedron | icosahedron | geodesic42 | geodesic162 | "
                     "geodesic642 | geodesic2562");
}

std::vector<std::string> particle_mesh_names()
{
    return {"tetrahedron", "octahedron", "icosahedron", "geodesic42", "geodesic162", "geodesic642"};
}

} // namespace softgrain::dpm
