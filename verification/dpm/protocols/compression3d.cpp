// DPM section 9.3.4, Fig. 9.11, eqs. (9.15)-(9.17): the 3D bodies compressed between plates.
// Laws: the elastic-tetrahedra energy (forces and Hessian against central finite differences; the patch
// test: a homogeneous deformation F gives J_f = F in every tetrahedron, the energy V0 W(F), the stress
// dU/dF = V0 P(F) and no force on the central vertex; frame indifference), the 3D spring and the 3D plate
// law, the affine moduli of the 3D network, and the exponents of F against delta at small and large
// compression (decision dpm-compress3d-windows).
#include "core/fits.hpp"
#include "core/rng.hpp"
#include "dpm/laws/shape_energy3d.hpp"
#include "dpm/laws/spring_network.hpp"
#include "dpm/protocols/compress3d.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Geometry>

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

const IsotropicElasticity steel_like = IsotropicElasticity::from_young(1.0, 0.3);

// The reference state of the body mapped by x -> F x + c (every vertex, the central one included).
Eigen::VectorXd affine_map(const ElasticTetrahedra& body, const Eigen::Matrix3d& F, const Eigen::Vector3d& c)
{
    Eigen::VectorXd x = body.reference;
    for (Eigen::Index p = 0; p < x.size() / 3; ++p)
        x.segment<3>(3 * p) = F * body.reference.segment<3>(3 * p) + c;
    return x;
}

// Strain energy density lambda/2 (tr E)^2 + mu E:E and first Piola-Kirchhoff stress P = F S, S = lambda tr E
// I
// + 2 mu E, written out independently of the kernel.
double density(const Eigen::Matrix3d& F, const IsotropicElasticity& c)
{
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    return 0.5 * c.lambda * E.trace() * E.trace() + c.mu * (E.array() * E.array()).sum();
}
Eigen::Matrix3d piola_stress(const Eigen::Matrix3d& F, const IsotropicElasticity& c)
{
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    return F * (c.lambda * E.trace() * Eigen::Matrix3d::Identity() + 2 * c.mu * E);
}

} // namespace

TEST_CASE("elastic tetrahedra: forces and Hessian are the derivatives of eq. (9.15) [DPM eqs. (9.15)-(9.17)]")
{
    const ElasticTetrahedra body = elastic_tetrahedra(compression_mesh("icosahedron"), steel_like);
    Rng rng(7);
    Eigen::VectorXd x = body.reference; // every coordinate displaced by up to 0.1 edge
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x(i) += 0.1 * rng.uniform(-1, 1);
    const auto dofs = x.size();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const double u = tetrahedra_energy(body, x, &g, &h);
    CHECK(u > 0);
    // Central differences with step 1e-5 (edge 1): truncation O(step^2 |U'''|) ~ 1e-10, round-off
    // O(round_off U/step) ~ 1e-11, against gradients O(0.1): 1e-7 absolute covers both with margin.
    const double step = 1e-5;
    for (Eigen::Index i = 0; i < dofs; ++i) {
        Eigen::VectorXd plus = x, minus = x;
        plus(i) += step;
        minus(i) -= step;
        const double g_fd = (tetrahedra_energy(body, plus, nullptr, nullptr) -
                             tetrahedra_energy(body, minus, nullptr, nullptr)) /
                            (2 * step);
        CHECK_CLOSE(g(i), g_fd, (Tolerance{0, 1e-7}));
        Eigen::VectorXd g_plus = Eigen::VectorXd::Zero(dofs), g_minus = Eigen::VectorXd::Zero(dofs);
        tetrahedra_energy(body, plus, &g_plus, nullptr);
        tetrahedra_energy(body, minus, &g_minus, nullptr);
        const Eigen::VectorXd column = (g_plus - g_minus) / (2 * step);
        // Same truncation and round-off estimate one derivative higher: 1e-6 absolute for entries O(1).
        for (Eigen::Index j = 0; j < dofs; ++j)
            CHECK_CLOSE(h(j, i), column(j), (Tolerance{0, 1e-6}));
    }
    CHECK_CLOSE((h - h.transpose()).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 100 * round_off}));
}

TEST_CASE("patch test: a homogeneous deformation F gives J_f = F, U = V0 W(F), dU/dF = V0 P and no force on "
          "the central vertex [DPM eqs. (9.15)-(9.17)]")
{
    for (const std::string mesh : {"icosahedron", "geodesic42", "geodesic162"}) {
        const ElasticTetrahedra body = elastic_tetrahedra(compression_mesh(mesh), steel_like);
        double v0 = 0;
        for (const auto& t : body.tetrahedra)
            v0 += t.reference_volume;
        // The star of tetrahedra about the central vertex tiles the polyhedron: V0 = its volume.
        const Eigen::VectorXd surface = body.reference.head(3 * body.centre());
        CHECK_CLOSE(v0, mesh_volume(body.mesh, surface, 0), (Tolerance{100 * round_off, 0}));
        Eigen::Matrix3d F;
        F << 1.10, 0.05, -0.02, 0.03, 0.92, 0.04, -0.06, 0.01, 1.05; // stretch, compression and shear
        const Eigen::VectorXd x = affine_map(body, F, Eigen::Vector3d(0.3, -0.7, 1.1));
        for (int f = 0; f < body.mesh.face_count(); ++f) {
            const auto local = gather<3, 4>(x, tetrahedron_points(body, f));
            const Eigen::Matrix3d J =
                body.tetrahedra[static_cast<std::size_t>(f)].deformation_gradient(local);
            CHECK_CLOSE((J - F).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 100 * round_off}));
        }
        Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
        const double u = tetrahedra_energy(body, x, &g, nullptr);
        // A sum of 2N - 4 terms, each exact to a few round-offs.
        CHECK_CLOSE(u, v0 * density(F, steel_like), (Tolerance{1e-13, 0}));
        // dU/dF = sum_p grad_p U X_p^T over all points at their reference positions X_p (chain rule).
        Eigen::Matrix3d dU_dF = Eigen::Matrix3d::Zero();
        double largest = 0;
        for (int p = 0; p <= body.centre(); ++p) {
            dU_dF += g.segment<3>(3 * p) * body.reference.segment<3>(3 * p).transpose();
            if (p < body.centre()) largest = std::max(largest, g.segment<3>(3 * p).norm());
        }
        const Eigen::Matrix3d P = v0 * piola_stress(F, steel_like);
        CHECK_CLOSE((dU_dF - P).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 1e-12 * P.cwiseAbs().maxCoeff()}));
        // The central vertex receives sum_f v_f P X_f^-T (1,1,1)^T... = P times the sum of the faces' area
        // vectors, zero for a closed surface: round-off of 2N - 4 terms of the size of a surface force.
        CHECK_CLOSE(g.segment<3>(3 * body.centre()).norm(), 0.0,
                    (Tolerance{0, 10.0 * body.mesh.face_count() * round_off * largest}));
    }
}

TEST_CASE("elastic tetrahedra: a rigid rotation costs no energy (Green strain) [DPM eq. (9.15)]")
{
    const ElasticTetrahedra body = elastic_tetrahedra(compression_mesh("geodesic42"), steel_like);
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    // (J^T J - I)/2 with J = Q: round-off O(round_off) per entry, times E v0 ~ 20.
    CHECK_CLOSE(tetrahedra_energy(body, affine_map(body, Q, Eigen::Vector3d(1, 1, 1)), nullptr, nullptr), 0.0,
                (Tolerance{0, 1e-26}));
}

TEST_CASE("3D spring k/2 (|r1 - r0| - l0)^2 and plate law k_p/2 (sigma/2 - z)^2: gradients [DPM sec. 9.3.4]")
{
    const SpringEnergy<3> spring{2.0, 0.8};
    Eigen::Matrix<double, 6, 1> x;
    x << 0.1, -0.2, 0.3, 0.5, 0.4, -0.3;
    const auto d = local_gradient<6>(spring, x);
    const Eigen::Vector3d r = x.tail<3>() - x.head<3>();
    const double stretch = r.norm() - 0.8;
    CHECK_CLOSE(d.value, 0.5 * 2.0 * stretch * stretch, (Tolerance{4 * round_off, 0}));
    for (int c = 0; c < 3; ++c) { // analytic: grad_1 = k (l - l0) r/|r| = -grad_0
        CHECK_CLOSE(d.gradient(3 + c), 2.0 * stretch * r(c) / r.norm(), (Tolerance{8 * round_off, 1e-16}));
        CHECK_CLOSE(d.gradient(c), -d.gradient(3 + c), (Tolerance{0, 0}));
    }
    // Plates normal to z: bottom at 0 facing up, top at 3 facing down; a vertex 0.2 inside each range.
    for (const double facing : {1.0, -1.0}) {
        const PlateEnergy plate{4.0, 0.5, facing > 0 ? 0.0 : 3.0, facing};
        const Eigen::Matrix<double, 3, 1> p(0.4, -0.1, facing > 0 ? 0.3 : 2.7);
        const auto e = local_hessian<3>(plate, p);
        // The overlap 0.5 - |z - y| = 0.2 is formed from decimal inputs: relative error ~ 3 round_off/0.2,
        // doubled in the square.
        CHECK_CLOSE(e.value, 0.5 * 4.0 * 0.2 * 0.2, (Tolerance{40 * round_off, 0}));
        CHECK_CLOSE(-e.gradient(2), facing * 4.0 * 0.2, (Tolerance{20 * round_off, 0}));
        CHECK(e.gradient(0) == 0.0);
        CHECK(e.gradient(1) == 0.0);
        CHECK_CLOSE(e.hessian(2, 2), 4.0, (Tolerance{round_off, 0}));
    }
}

TEST_CASE("3D network ball: node count, and its affine energy under uniaxial strain is V (lambda + 2 mu)/2 "
          "eps^2 with lambda = mu = sum k l^2/(15 V) [decision dpm-spring-network3d]")
{
    const SpringNetwork network = disordered_sphere_network(600, 1.8, 1.0, 3);
    CHECK(network.node_count() == 600);
    const double z = 2.0 * static_cast<double>(network.springs.size()) / network.node_count();
    CHECK(z > 12); // far above isostaticity (6): a rigid network
    // The affine estimate assumes isotropic bond directions, <n_z^4> = 1/5. The ball is isotropic only on
    // average: its Fibonacci surface layer spirals about z; measured 5 <n_z^4> = 0.967 ... 1.044 over seeds
    // 1-3 at 600, 1000 and 3765 nodes (x, y: 0.987 ... 1.031). 5 % allowed.
    const double eps = 1e-4;
    Eigen::VectorXd x = network.x;
    for (Eigen::Index p = 0; p < x.size() / 3; ++p)
        x(3 * p + 2) *= 1 + eps;
    double sum_kl2 = 0;
    for (const Spring& s : network.springs)
        sum_kl2 += network.k * s.rest_length * s.rest_length;
    const double volume = 1; // U = (V/2) (lambda + 2 mu) eps^2 = (1/2) eps^2 sum k l^2 / 5 for any V
    CHECK_CLOSE(spring_network_energy(network, x, nullptr), 0.5 * eps * eps * sum_kl2 / 5 * volume,
                (Tolerance{0.05, 0}));
    // E = 5 mu/2 = sum k l^2/(6 V), nu = 1/4 (Cauchy relation lambda = mu).
    CHECK_CLOSE(affine_network_young_modulus(network, 2.0), sum_kl2 / 12, (Tolerance{round_off * 10, 0}));
}

TEST_CASE("tetrahedra and shell between plates: F proportional to delta while the pole vertex alone touches "
          "[DPM sec. 9.3.4, Fig. 9.11(d)]")
{
    Compression3dOptions o;
    o.mesh = "geodesic42"; // the pole vertex alone touches up to delta/D ~ 0.1
    o.schedule.delta_min = 1e-3;
    o.schedule.delta_max = 3e-3;
    o.schedule.steps = 4;
    o.schedule.force_tolerance = 1e-10;
    for (const bool shell : {false, true}) {
        const Compression3dResult r = shell ? compress3d_shell(o) : compress3d_tetrahedra(o);
        std::vector<double> delta, force;
        for (const auto& s : r.compression.samples) {
            CHECK(s.top_contacts == 1);
            delta.push_back(s.delta_over_d);
            force.push_back(s.force);
        }
        // One contact vertex on a linear elastic body: exactly linear but for geometric nonlinearity,
        // O(delta/edge) = O(D delta~) ~ 0.01 at delta~ = 3e-3 (D ~ 4.4 edges) on the local slope; 0.01 on the
        // fitted mean slope (measured 0.996 tetrahedra, 1.001 shell).
        CHECK_CLOSE(fit_power_law_exponent(delta, force).value(), 1.0, (Tolerance{0, 0.01}));
    }
}

TEST_CASE(
    "elastic tetrahedra (N = 162) at large compression: F ~ delta^1.5 +- 0.1 for 0.05 <= delta/D <= 0.2 "
    "[DPM sec. 9.3.4, Fig. 9.11(d)]")
{
    Compression3dOptions o; // geodesic162, E = 1 k_c/sigma, nu = 0.3, k_p = 4 k_c
    o.schedule.delta_min = 0.05;
    o.schedule.delta_max = 0.2;
    o.schedule.steps = 7;
    o.schedule.force_tolerance = 1e-8;
    const Compression3dResult r = compress3d_tetrahedra(o);
    std::vector<double> delta, force;
    for (const auto& s : r.compression.samples) {
        CHECK(s.top_contacts >= 6); // the pole vertex and at least its first ring: a contact patch
        delta.push_back(s.delta_over_d);
        force.push_back(s.force);
    }
    // The paper's alpha = 1.5 "for sufficiently large displacements" (decision dpm-compress3d-windows). The
    // tolerance is the contact staircase: rings of vertices reach the plate one at a time and the local
    // exponent swings between 1.1 and 2.3 inside the window (measured fit 1.449). It holds at the paper's
    // mesh only: the exponent drifts with the mesh (642 vertices: 1.34), see DPM-Fig9.11-meshes.
    CHECK_CLOSE(fit_power_law_exponent(delta, force).value(), 1.5, (Tolerance{0, 0.1}));
}

TEST_CASE("elastic shell (N = 162): F proportional to delta over the range in which the pole vertex alone "
          "touches, delta/D <= 0.1 [DPM sec. 9.3.4, Fig. 9.11(d)]")
{
    Compression3dOptions o; // geodesic162, k_v = 1e-3, k_a = 1, k_b = 1 (decision dpm-compress3d-shell)
    o.schedule.delta_min = 1e-3;
    o.schedule.delta_max = 0.1;
    o.schedule.steps = 6;
    o.schedule.force_tolerance = 1e-8;
    const Compression3dResult r = compress3d_shell(o);
    std::vector<double> delta, force;
    for (const auto& s : r.compression.samples) {
        CHECK(s.top_contacts == 1);
        delta.push_back(s.delta_over_d);
        force.push_back(s.force);
    }
    // A point load on a shell: linear at small delta; the local exponent rises from 1.00 to 1.10 at
    // delta/D = 0.1 (geometric stiffening of the indented cap); measured fit 1.022. 0.1: the paper's
    // "F~ proportional to delta~ over a large range".
    CHECK_CLOSE(fit_power_law_exponent(delta, force).value(), 1.0, (Tolerance{0, 0.1}));
}

TEST_CASE("compression meshes: a vertex and its antipode on the z axis, mean edge = sigma = 1 [decision "
          "dpm-compress3d-units]")
{
    for (const std::string name : {"icosahedron", "geodesic42", "geodesic162", "geodesic642"}) {
        const TriangleMesh mesh = compression_mesh(name);
        const Eigen::VectorXd z = mesh.vertices.row(2).transpose();
        const double R = mesh.vertices.col(0).norm();
        // A rotation of a unit-sphere mesh followed by one scaling: round-off of a few operations.
        CHECK_CLOSE(mesh.vertices(2, 0), R, (Tolerance{10 * round_off, 0}));
        CHECK_CLOSE(z.minCoeff(), -R, (Tolerance{10 * round_off, 0}));
        double edge = 0;
        for (const MeshEdge& e : mesh.edges)
            edge += (mesh.vertices.col(e.a) - mesh.vertices.col(e.b)).norm();
        CHECK_CLOSE(edge / mesh.edge_count(), 1.0, (Tolerance{mesh.edge_count() * round_off, 0}));
    }
}
