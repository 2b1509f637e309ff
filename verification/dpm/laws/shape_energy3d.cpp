// DPM eq. (9.2): every term of the 3D shape energy (volume, face area, dihedral bending, surface tension).
// Forces are minus the gradient and the Hessian is the derivative of the gradient (central finite
// differences on randomly perturbed meshes); exact identities: invariance under rigid motions (forces and
// torques sum to zero) and Euler's theorem for homogeneous measures, x . grad v = 3 v, x . grad s = 2 s,
// x . grad theta_e = 0 (angles are scale-free), which fixes the gradients' scale independently of any
// finite difference.
#include "dpm/laws/shape_energy3d.hpp"
#include "core/rng.hpp"
#include "support/derivatives.hpp"
#include "support/tolerance.hpp"

#include <Eigen/SparseCore>
#include <vector>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_against_central_differences;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// The mesh's vertices shifted off the origin and displaced by up to `noise` times the mean edge.
Eigen::VectorXd perturbed(const TriangleMesh& mesh, double noise, Rng& rng)
{
    Eigen::VectorXd x = mesh_coordinates(mesh);
    double edge = 0;
    for (const auto& e : mesh.edges)
        edge += (mesh.vertices.col(e.a) - mesh.vertices.col(e.b)).norm();
    edge /= mesh.edge_count();
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x(i) += (i % 3 == 0 ? 0.3 : -0.2) + noise * edge * rng.uniform(-1, 1);
    return x;
}

// Random stiffnesses and rest values near the mesh's own (so that no penalty is trivially at its minimum).
ShapeParameters3d random_parameters(const TriangleMesh& mesh, Rng& rng)
{
    const Eigen::VectorXd x = mesh_coordinates(mesh);
    ShapeParameters3d s = rest_shape_from_mesh(mesh, x, rng.uniform(0.5, 2), rng.uniform(0.5, 2),
                                               rng.uniform(0.5, 2), rng.uniform(0.5, 2));
    s.v0 *= rng.uniform(0.8, 1.2);
    for (double& a : s.a0)
        a *= rng.uniform(0.8, 1.2);
    for (double& t : s.theta0)
        t *= rng.uniform(0.5, 1.5);
    return s;
}

void check_derivatives(const ShapeParameters3d& s, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                       unsigned term)
{
    const auto dofs = x.size();
    const int n = mesh.vertex_count();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const double energy = shape_energy3d(s, mesh, x, 0, &g, &h, term);
    // Value alone and with derivatives is the same code, evaluated in double or in AutoDiff (different
    // rounding): equal to round-off of the O(N_f)-term sums of O(1) measures, absolute since the volume
    // penalty k_v/2 (v - v0)^2 may be small after the cancellation in v - v0.
    CHECK_CLOSE(shape_energy3d(s, mesh, x, 0, nullptr, nullptr, term), energy,
                (Tolerance{10 * round_off, 100 * round_off}));
    // The gradient alone and the one beside the Hessian sum the same analytic slopes in two orders:
    // round-off of sums over the <= 6 faces or 12 hinges at a vertex (and, for the volume, of the product
    // k_v (v - v0) grad v), so 1000 eps of the largest component.
    Eigen::VectorXd g_analytic = Eigen::VectorXd::Zero(dofs);
    CHECK_CLOSE(shape_energy3d(s, mesh, x, 0, &g_analytic, nullptr, term), energy,
                (Tolerance{10 * round_off, 100 * round_off}));
    CHECK_CLOSE((g_analytic - g).cwiseAbs().maxCoeff(), 0.0,
                (Tolerance{0, 1000 * round_off * std::max(1.0, g.cwiseAbs().maxCoeff())}));
    check_against_central_differences(
        [&](const Eigen::VectorXd& y, Eigen::VectorXd* gy, Eigen::MatrixXd* hy) {
            return shape_energy3d(s, mesh, y, 0, gy, hy, term);
        },
        x, g, h);
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    const double h_scale = std::max(1.0, h.cwiseAbs().maxCoeff());
    CHECK_CLOSE((h - h.transpose()).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 100 * round_off * h_scale}));
    // Into a sparse sink the particle's Hessian goes as one dense block (with_dense_block): the same
    // additions in the same order as into the dense matrix, so the same numbers to the bit, one triplet
    // per entry.
    std::vector<Eigen::Triplet<double>> triplets;
    shape_energy3d(s, mesh, x, 0, nullptr, &triplets, term);
    CHECK(triplets.size() == static_cast<std::size_t>(dofs * dofs));
    Eigen::SparseMatrix<double> sparse(dofs, dofs);
    sparse.setFromTriplets(triplets.begin(), triplets.end());
    CHECK((Eigen::MatrixXd(sparse) - h).cwiseAbs().maxCoeff() == 0.0);
    // Rigid-motion invariance: sum of forces and sum of torques r x F vanish (round-off of N terms).
    const Eigen::Matrix3Xd r = x.reshaped(3, n), f = g.reshaped(3, n);
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i)
        torque += r.col(i).cross(f.col(i));
    CHECK_CLOSE(f.rowwise().sum().norm(), 0.0, (Tolerance{0, 1000 * round_off * g_scale}));
    CHECK_CLOSE(torque.norm(), 0.0, (Tolerance{0, 1000 * round_off * g_scale}));
}

} // namespace

TEST_CASE(
    "forces = -grad U and Hessian = d(grad U) for each term of eq. (9.2), random meshes [DPM eq. (9.2)]")
{
    Rng rng(90201);
    const std::pair<unsigned, const char*> terms[] = {{volume_term3d, "volume"},
                                                      {face_area_term3d, "face area"},
                                                      {bending_term3d, "dihedral bending"},
                                                      {surface_tension_term3d, "surface tension"},
                                                      {all_shape_terms3d, "all terms"}};
    for (const char* name : {"tetrahedron", "icosahedron", "geodesic42"}) {
        const TriangleMesh mesh = mesh_from_name(name);
        for (int trial = 0; trial < 2; ++trial) {
            const ShapeParameters3d s = random_parameters(mesh, rng);
            const Eigen::VectorXd x = perturbed(mesh, 0.2, rng);
            for (const auto& [term, term_name] : terms) {
                CAPTURE(std::string(name));
                CAPTURE(std::string(term_name));
                check_derivatives(s, mesh, x, term);
            }
        }
    }
}

TEST_CASE("Euler's theorem: x . grad v = 3 v, x . grad s = 2 s, x . grad theta = 0 [DPM eq. (9.2)]")
{
    // With k_v = 1, v0 = v - 1: grad U_v = (v - v0) grad v = grad v; with gamma = 1: grad U = grad s; with
    // k_b = 1, theta0 = theta - 1: grad U_b = sum_e grad theta_e. Dilation about the origin scales v by
    // lambda^3, s by lambda^2 and leaves angles unchanged: exact identities, checked to round-off.
    Rng rng(90202);
    const TriangleMesh mesh = mesh_from_name("geodesic42");
    const Eigen::VectorXd x = perturbed(mesh, 0.2, rng);
    ShapeParameters3d s = rest_shape_from_mesh(mesh, x, 1, 0, 1, 1);
    s.v0 -= 1;
    for (double& t : s.theta0)
        t -= 1;
    const double volume = mesh_volume(mesh, x, 0), surface = mesh_surface_area(mesh, x, 0);
    for (const auto& [term, expected] :
         {std::pair{volume_term3d, 3 * volume}, std::pair{surface_tension_term3d, 2 * surface},
          std::pair{bending_term3d, 0.0}}) {
        Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
        shape_energy3d(s, mesh, x, 0, &g, nullptr, term);
        CHECK_CLOSE(x.dot(g), expected, (Tolerance{1000 * round_off, 1000 * round_off}));
    }
    // Translation leaves v and s unchanged although each face volume r0 . (r1 x r2)/6 changes.
    Eigen::VectorXd shifted = x;
    for (int i = 0; i < mesh.vertex_count(); ++i)
        shifted.segment<3>(3 * i) += Eigen::Vector3d(1.5, -2.0, 0.7);
    CHECK_CLOSE(mesh_volume(mesh, shifted, 0), volume, (Tolerance{1000 * round_off, 0}));
}

TEST_CASE("the undeformed mesh is a zero-energy state of its own rest shape [DPM eq. (9.2)]")
{
    for (const char* name : {"octahedron", "geodesic162"}) {
        CAPTURE(std::string(name));
        const TriangleMesh mesh = mesh_from_name(name);
        const Eigen::VectorXd x = mesh_coordinates(mesh);
        const ShapeParameters3d s = rest_shape_from_mesh(mesh, x, 1, 1, 1, 0);
        Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
        CHECK_CLOSE(shape_energy3d(s, mesh, x, 0, &g, nullptr), 0.0, (Tolerance{0, round_off}));
        CHECK_CLOSE(g.cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 100 * round_off}));
    }
}

TEST_CASE("analytic slopes of face volume, triangle area and dihedral angle and their Jacobians = AutoDiff "
          "gradients and Hessians to round-off [DPM eq. (9.2)]")
{
    // The same derivatives in two roundings: the analytic slopes (shape_energy3d.hpp) in double and,
    // through their forward-mode Jacobian, the Hessian (local_hessian_from_slope), against forward AutoDiff
    // of the measures themselves, once and nested. Each gradient component is a short sum of products of
    // O(1) coordinates, so they agree to a few eps times the measure's gradient scale (its largest
    // component); 64 eps leaves room for the atan2 quotient of the dihedral angle, while a wrong sign or
    // term is an O(1) relative error. A Hessian entry is one derivative more of such quotients: 256 eps of
    // the Hessian's scale. The values are the same double code as the AutoDiff value part up to the order
    // of operations that Eigen's AutoDiff products take: a few eps of the O(1) measure.
    // Random triangles and hinges with bending angles over (-pi, pi), convex and concave.
    Rng rng(90203);
    const auto point = [&rng] {
        return Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    };
    const auto check = [](const auto& measure, const auto& slope, const auto& x) {
        constexpr int n = std::decay_t<decltype(x)>::RowsAtCompileTime;
        const auto autodiff = local_hessian<n>(measure, x);
        const auto analytic = local_hessian_from_slope<n>(measure, slope, x);
        const double scale = autodiff.gradient.cwiseAbs().maxCoeff();
        CHECK_CLOSE(analytic.value, autodiff.value, (Tolerance{0, 4 * round_off}));
        CHECK_CLOSE((slope(x, measure(x)) - autodiff.gradient).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 64 * round_off * scale}));
        // The value part of the AutoDiff sweep: the same formulas, grouped as Eigen's AutoDiff takes them.
        CHECK_CLOSE((analytic.gradient - slope(x, measure(x))).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 4 * round_off * scale}));
        CHECK_CLOSE((analytic.hessian - autodiff.hessian).cwiseAbs().maxCoeff(), 0.0,
                    (Tolerance{0, 256 * round_off * autodiff.hessian.cwiseAbs().maxCoeff()}));
        CHECK(analytic.hessian == analytic.hessian.transpose());
    };
    double smallest_angle = 0, largest_angle = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Eigen::Matrix<double, 9, 1> face;
        face << point(), point(), point();
        check(face_volume, face_volume_slope, face);
        check(triangle_area, triangle_area_slope, face);
        Eigen::Matrix<double, 12, 1> hinge;
        hinge << point(), point(), point(), point();
        check(dihedral_angle, dihedral_angle_slope, hinge);
        smallest_angle = std::min(smallest_angle, dihedral_angle(hinge));
        largest_angle = std::max(largest_angle, dihedral_angle(hinge));
    }
    // Both signs of the angle, close to +-pi, were met (the samples cover the branch of atan2).
    CHECK(smallest_angle < -3.0);
    CHECK(largest_angle > 3.0);
}
