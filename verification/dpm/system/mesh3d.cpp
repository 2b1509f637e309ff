// DPM section 9.3.1 (3D): closed triangulated surfaces. Euler counts N + N_f - N_e = 2, N_f = 2N - 4,
// N_e = 3N - 6 for every mesh; the shape parameter A^3D = s^(3/2)/(6 sqrt(pi) v) of the Platonic solids
// in closed form and against the text's 1.8188, 1.2861, 1.0984, of the 42-vertex geodesic icosahedron
// against 1.024; the closed-form bending angles of the regular meshes; A^3D -> 1 as O(1/N).
#include "core/fits.hpp"
#include "dpm/laws/shape_energy3d.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

const double pi = std::numbers::pi;

double shape_parameter_of(const TriangleMesh& mesh)
{
    const Eigen::VectorXd x = mesh_coordinates(mesh);
    return shape_parameter3d(mesh_surface_area(mesh, x, 0), mesh_volume(mesh, x, 0));
}

// A^3D of a regular solid of unit edge with surface s and volume v.
double closed_form_shape_parameter(double s, double v)
{
    return std::pow(s, 1.5) / (6 * std::sqrt(pi) * v);
}

} // namespace

TEST_CASE("Euler counts N + N_f - N_e = 2, N_f = 2N - 4, N_e = 3N - 6 for every mesh [DPM sec. 9.3.1]")
{
    const std::pair<const char*, int> meshes[] = {{"tetrahedron", 4},   {"octahedron", 6},
                                                  {"icosahedron", 12},  {"geodesic42", 42},
                                                  {"geodesic162", 162}, {"geodesic642", 642}};
    for (const auto& [name, n] : meshes) {
        CAPTURE(std::string(name));
        const TriangleMesh mesh = mesh_from_name(name);
        CHECK(mesh.vertex_count() == n);
        CHECK(mesh.face_count() == 2 * n - 4);
        CHECK(mesh.edge_count() == 3 * n - 6);
        CHECK(mesh.vertex_count() + mesh.face_count() - mesh.edge_count() == 2);
        // Every vertex on the unit sphere (subdivision + projection), every face outward: positive volume
        // contribution and a positive bending angle at every edge (a convex surface).
        CHECK_CLOSE((mesh.vertices.colwise().norm().array() - 1).abs().maxCoeff(), 0.0,
                    (Tolerance{0, 10 * round_off}));
        const Eigen::VectorXd x = mesh_coordinates(mesh);
        for (double theta : mesh_bending_angles(mesh, x, 0))
            CHECK(theta > 0);
        // Every vertex has at least 3 edges and the degrees add up to 2 N_e.
        std::vector<int> degree(n, 0);
        for (const auto& e : mesh.edges) {
            ++degree[e.a];
            ++degree[e.b];
        }
        CHECK(*std::min_element(degree.begin(), degree.end()) >= 3);
    }
}

TEST_CASE("A^3D of the Platonic solids in closed form and against the text [DPM sec. 9.3.1]")
{
    const double s3 = std::sqrt(3.0), r5 = std::sqrt(5.0);
    struct Case
    {
        const char* name;
        double closed_form, text, bending_angle;
    };
    // Unit edge: tetrahedron s = sqrt3, v = 1/(6 sqrt2); octahedron s = 2 sqrt3, v = sqrt2/3; icosahedron
    // s = 5 sqrt3, v = 5 (3 + sqrt5)/12. Bending angle = pi - interior dihedral angle: arccos(-1/3) ...
    const Case cases[] = {
        {"tetrahedron", closed_form_shape_parameter(s3, 1 / (6 * std::sqrt(2.0))), 1.8188,
         pi - std::acos(1.0 / 3.0)},
        {"octahedron", closed_form_shape_parameter(2 * s3, std::sqrt(2.0) / 3), 1.2861, std::acos(1.0 / 3.0)},
        {"icosahedron", closed_form_shape_parameter(5 * s3, 5 * (3 + r5) / 12), 1.0984, std::acos(r5 / 3)},
    };
    for (const auto& c : cases) {
        CAPTURE(std::string(c.name));
        const TriangleMesh mesh = mesh_from_name(c.name);
        const double a = shape_parameter_of(mesh);
        // Same number by two routes (mesh sums vs closed form): round-off.
        CHECK_CLOSE(a, c.closed_form, (Tolerance{100 * round_off, 0}));
        // The text quotes 4 decimals: agreement to its last digit (the issue asks for 1e-4).
        CHECK_CLOSE(a, c.text, (Tolerance{0, 1e-4}));
        const Eigen::VectorXd x = mesh_coordinates(mesh);
        for (double theta : mesh_bending_angles(mesh, x, 0))
            CHECK_CLOSE(theta, c.bending_angle, (Tolerance{0, 100 * round_off}));
        const std::vector<double> areas = mesh_face_areas(mesh, x, 0);
        for (double area : areas)
            CHECK_CLOSE(area, areas.front(), (Tolerance{100 * round_off, 0}));
    }
}

TEST_CASE("geodesic icosahedra: A^3D(42) = 1.024 and A^3D - 1 = O(1/N) [DPM sec. 9.3.1]")
{
    // The text quotes 1.024 (3 decimals) for N = 42: agreement to half a unit of its last digit.
    CHECK_CLOSE(shape_parameter_of(mesh_from_name("geodesic42")), 1.024, (Tolerance{0, 5e-4}));
    // An inscribed mesh of edge h ~ N^(-1/2) misses area and volume at O(h^2), so A - 1 ~ N^(-1); the fitted
    // slope of ln(A - 1) against ln N over N = 42, 162, 642 must be -1 within 0.1 (the pre-asymptotic
    // curvature of three points; a wrong projection or orientation gives slope 0 or a sign change).
    std::vector<double> vertex_counts, excess_shape_parameters;
    double previous = 2;
    for (int s = 1; s <= 3; ++s) {
        const TriangleMesh mesh = geodesic_icosahedron(s);
        const double a = shape_parameter_of(mesh);
        CHECK(a < previous);
        CHECK(a > 1); // the sphere is the minimum (isoperimetric inequality)
        previous = a;
        vertex_counts.push_back(mesh.vertex_count());
        excess_shape_parameters.push_back(a - 1);
    }
    CHECK_CLOSE(fit_power_law_exponent(vertex_counts, excess_shape_parameters).value(), -1.0,
                (Tolerance{0, 0.1}));
}
