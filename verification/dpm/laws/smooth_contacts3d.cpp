// DPM section 9.3.2 in 3D (Fig. 9.6d): smooth contacts between sphero-polyhedral particles, a vertex
// against the faces of the other particle (interactions3d.hpp, decisions dpm-3d-smooth-inclusion-exclusion
// and dpm-3d-smooth-both-ways).
//   * point-triangle distance against brute-force sampling of the triangle, in all seven Voronoi regions;
//   * its value and gradient continuous across every region boundary (face|edge, edge|vertex);
//   * forces = -grad U and Hessian = d(grad U) by finite differences on overlapping, slightly non-convex
//     particles (concave edges), across a periodic boundary; forces and torques sum to zero;
//   * the virial pressure equals -dU/dV under homogeneous dilation (as for rough contacts);
//   * through a Lees-Edwards sheared boundary: the sheared lattice vector leaves U unchanged, forces,
//     Hessian and virial pressure as above; a particle touching two images of another in a small box has
//     the energy of the same copies in open space;
//   * a particle pressed on a flat mesh: the vertex-against-surface energy is the same wherever the contact
//     point lies on the mesh (face interior, edge, vertex), while rough contacts corrugate (closed forms);
//     a vertex pushed through a face is a NumericalError;
//   * the terms found by the vertex-level Verlet list (vertex_pairs3d.hpp) give the energy of a sum over
//     every particle pair, feature and image without any search, also where one vertex touches two images
//     of a particle; energy, gradient, Hessian, virial and contact counts do not depend on when the list
//     was built (bit for bit); the list takes the smooth range and refuses a box below it.
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/laws/interactions3d.hpp"
#include "dpm/protocols/single_particle3d.hpp"
#include "dpm/system/system3d.hpp"
#include "support/derivatives.hpp"
#include "support/jammed3d.hpp"
#include "support/tolerance.hpp"

#include <set>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_against_central_differences;
using softgrain::verification::check_same_with_fresh_list3d;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

Eigen::Vector3d random_point(Rng& rng, double half_width)
{
    return {rng.uniform(-half_width, half_width), rng.uniform(-half_width, half_width),
            rng.uniform(-half_width, half_width)};
}

Eigen::Matrix<double, 12, 1> stack(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
    Eigen::Matrix<double, 12, 1> x;
    x << p, a, b, c;
    return x;
}

struct TriangleDistance
{
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 12, 1>& x) const
    {
        return point_triangle_distance(x);
    }
};

// A random rotation from a normalised quaternion of normal deviates.
Eigen::Matrix3d random_rotation(Rng& rng)
{
    Eigen::Quaterniond q(rng.normal(1), rng.normal(1), rng.normal(1), rng.normal(1));
    q.normalize();
    return q.toRotationMatrix();
}

// Three icosahedra (circumradius 1, inradius 0.795) in random orientations, centres 2.2 apart along x,
// vertices displaced by up to 0.04 per coordinate (some edges turn concave), vertex diameter 0.9: their
// hulls stay 2.2 - 2 (1 + 0.07) > 0 apart (no vertex inside another particle) and their faces closer than
// 2.2 - 2 (0.795 - 0.07) < 0.9 (contacts). With a box (side 6.6), particle 2 touches particle 0 through
// the boundary x = 0.
DpmSystem3d smooth_trio(Rng& rng, bool periodic, Eigen::VectorXd& x)
{
    DpmSystem3d s;
    s.interaction = InteractionKind::smooth;
    s.kc = rng.uniform(0.5, 2.0);
    if (periodic) s.box = 6.6;
    s.meshes.push_back(icosahedron_mesh());
    for (int m = 0; m < 3; ++m) {
        const Eigen::Vector3d centre(0.4 + 2.2 * m, 3.3, 3.3);
        Eigen::Matrix3Xd v = (random_rotation(rng) * s.meshes[0].vertices).colwise() + centre;
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.04 * rng.uniform(-1, 1);
        s.add_particle(0, v, 0.9, ShapeParameters3d{}, x);
    }
    return s;
}

// The trio turned by 90 degrees about z (chain along y, through the boundary y = 0) in a box sheared by the
// Lees-Edwards strain gamma: particle 2 moved by gamma L in x so that the sheared image of particle 0 one box
// up in y touches it (particles 1 and 2 then no longer touch).
DpmSystem3d sheared_trio(Rng& rng, double gamma, Eigen::VectorXd& x)
{
    DpmSystem3d s = smooth_trio(rng, true, x);
    const double L = *s.box;
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) {
        const Eigen::Vector3d r = x.segment<3>(3 * v);
        x.segment<3>(3 * v) = Eigen::Vector3d(L - r.y(), r.x(), r.z());
    }
    const Particle3d& last = s.particles[2];
    for (int v = last.first; v < last.first + last.count; ++v)
        x(3 * v) += gamma * L;
    s.lees_edwards_strain = gamma;
    return s;
}

// The smooth interaction energy summed without any pair search: every vertex of every particle against
// every face, edge and vertex of every other particle at every image n in {-2, ..., 2}^3 of the sheared
// lattice, each term k_c/4 (sigma_mb - d)^2 Theta(sigma_mb - d) (the 1/2 of eq. 9.5 and the
// inclusion-exclusion signs of interactions3d.hpp).
double smooth_energy_over_all_images(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    const int reach = s.box ? 2 : 0;
    const double L = s.box.value_or(0), gamma = s.lees_edwards_strain;
    const auto term = [&](double d, double sigma) {
        return d < sigma ? 0.25 * s.kc * (sigma - d) * (sigma - d) : 0.0;
    };
    double energy = 0;
    for (const Particle3d& a : s.particles)
        for (const Particle3d& b : s.particles) {
            if (&a == &b) continue;
            const TriangleMesh& mesh = s.meshes[b.mesh];
            const double sigma = 0.5 * (a.sigma + b.sigma);
            for (int nx = -reach; nx <= reach; ++nx)
                for (int ny = -reach; ny <= reach; ++ny)
                    for (int nz = -reach; nz <= reach; ++nz) {
                        const Eigen::Vector3d shift((nx + ny * gamma) * L, ny * L, nz * L);
                        const auto point = [&](int v) {
                            return Eigen::Vector3d(x.segment<3>(3 * (b.first + v)) + shift);
                        };
                        for (int i = a.first; i < a.first + a.count; ++i) {
                            const Eigen::Vector3d p = x.segment<3>(3 * i);
                            for (const auto& f : mesh.faces) {
                                Eigen::Matrix<double, 12, 1> local;
                                local << p, point(f[0]), point(f[1]), point(f[2]);
                                energy += term(point_triangle_distance(local), sigma);
                            }
                            for (const MeshEdge& e : mesh.edges) {
                                Eigen::Matrix<double, 9, 1> local;
                                local << p, point(e.a), point(e.b);
                                energy -= term(point_segment_distance(local), sigma);
                            }
                            for (int v = 0; v < b.count; ++v)
                                energy += term((point(v) - p).norm(), sigma);
                        }
                    }
        }
    return energy;
}

} // namespace

TEST_CASE("point-triangle and point-segment distance = minimum over a fine sampling, all seven regions")
{
    Rng rng(5);
    std::set<TriangleFeature> seen;
    const int n = 300; // samples a + (i/n)(b - a) + (j/n)(c - a), i + j <= n
    for (int trial = 0; trial < 60; ++trial) {
        const Eigen::Vector3d a = random_point(rng, 1), b = random_point(rng, 1), c = random_point(rng, 1);
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        for (int q = 0; q < 4; ++q) {
            const Eigen::Vector3d p = (a + b + c) / 3 + random_point(rng, 2);
            seen.insert(nearest_triangle_feature(p, a, b, c));
            const double exact = point_triangle_distance(stack(p, a, b, c));
            double sampled = std::numeric_limits<double>::infinity();
            for (int i = 0; i <= n; ++i)
                for (int j = 0; i + j <= n; ++j)
                    sampled = std::min(sampled, (a + (b - a) * i / n + (c - a) * j / n - p).norm());
            // The nearest point lies in a grid triangle of diameter <= longest/n, so a sample is within
            // that of it; no sample can be nearer than the exact distance (up to round-off).
            CHECK_CLOSE(sampled, exact, (Tolerance{0, longest / n}));
            CHECK(sampled >= exact - 10 * round_off * (1 + exact));
            Eigen::Matrix<double, 9, 1> segment;
            segment << p, a, b;
            const double on_segment = point_segment_distance(segment);
            double segment_sampled = std::numeric_limits<double>::infinity();
            for (int i = 0; i <= 100 * n; ++i)
                segment_sampled = std::min(segment_sampled, (a + (b - a) * i / (100.0 * n) - p).norm());
            CHECK_CLOSE(segment_sampled, on_segment, (Tolerance{0, (b - a).norm() / (200.0 * n)}));
            CHECK(segment_sampled >= on_segment - 10 * round_off * (1 + on_segment));
        }
    }
    CHECK(seen.size() == 7); // face, three edges, three corners all met
}

TEST_CASE("point-triangle distance and its gradient are continuous across the region boundaries")
{
    Rng rng(9);
    const double eps = 1e-7;
    int crossings = 0;
    for (int trial = 0; trial < 20; ++trial) {
        std::array<Eigen::Vector3d, 3> corner{random_point(rng, 1), random_point(rng, 1),
                                              random_point(rng, 1)};
        const Eigen::Vector3d normal = (corner[1] - corner[0]).cross(corner[2] - corner[0]).normalized();
        for (int e = 0; e < 3; ++e) { // edge from corner e to corner e + 1, the third corner opposite
            const Eigen::Vector3d &a = corner[e], &b = corner[(e + 1) % 3], &c = corner[(e + 2) % 3];
            const Eigen::Vector3d along = (b - a).normalized();
            Eigen::Vector3d out = along.cross(normal);
            if (out.dot(c - a) > 0) out = -out; // in-plane, away from the triangle
            const double height = rng.uniform(-0.8, 0.8);
            // face | edge: on the plane through the edge normal to the triangle; edge | vertex: on the
            // plane through corner a normal to the edge.
            const Eigen::Vector3d face_edge = a + rng.uniform(0.1, 0.9) * (b - a) + height * normal,
                                  edge_vertex = a + rng.uniform(0.1, 0.8) * out + height * normal;
            for (const auto& [q, across] : {std::pair{face_edge, out}, std::pair{edge_vertex, along}}) {
                const Eigen::Vector3d plus = q + eps * across, minus = q - eps * across;
                CHECK(nearest_triangle_feature(plus, corner[0], corner[1], corner[2]) !=
                      nearest_triangle_feature(minus, corner[0], corner[1], corner[2])); // a real crossing
                const auto dp =
                    local_hessian<12>(TriangleDistance{}, stack(plus, corner[0], corner[1], corner[2]));
                const auto dm =
                    local_hessian<12>(TriangleDistance{}, stack(minus, corner[0], corner[1], corner[2]));
                // The distance is 1-Lipschitz in p; the gradient changes by at most 2 eps times the larger
                // Hessian (row-sum norm) on either side, with a factor 2 for the variation of the Hessian.
                CHECK_CLOSE(dp.value, dm.value, (Tolerance{0, 2 * eps + 10 * round_off}));
                const double curvature = std::max(dp.hessian.cwiseAbs().rowwise().sum().maxCoeff(),
                                                  dm.hessian.cwiseAbs().rowwise().sum().maxCoeff());
                CHECK_CLOSE((dp.gradient - dm.gradient).cwiseAbs().maxCoeff(), 0.0,
                            (Tolerance{0, 4 * eps * curvature + 1e3 * round_off}));
                ++crossings;
            }
        }
    }
    CHECK(crossings == 120);
}

TEST_CASE("3D smooth contacts: forces = -grad U, Hessian = d(grad U), forces and torques sum to zero")
{
    Rng rng(3);
    for (int sample = 0; sample < 4; ++sample) {
        const bool periodic = sample % 2 == 0;
        CAPTURE(sample);
        Eigen::VectorXd x;
        const DpmSystem3d s = smooth_trio(rng, periodic, x);
        const Eigen::Index dofs = x.size();
        Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
        const double energy = interaction_energy3d(s, x, &g, &h);
        CHECK(energy > 0);
        CHECK_CLOSE(interaction_energy3d(s, x, nullptr, nullptr), energy, (Tolerance{10 * round_off, 0}));
        const std::vector<int> contacts = contact_counts3d(s, x);
        CHECK(contacts[0] > 0);
        CHECK(contacts[2] > 0); // with the box, through the boundary as well
        check_against_central_differences(
            [&](const Eigen::VectorXd& y, Eigen::VectorXd* gy, Eigen::MatrixXd* hy) {
                return interaction_energy3d(s, y, gy, hy);
            },
            x, g, h);
        const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
        // Newton's third law: translation invariance of every term.
        const Eigen::Matrix3Xd forces = -g.reshaped(3, dofs / 3);
        CHECK_CLOSE(forces.rowwise().sum().norm(), 0.0, (Tolerance{0, 1e3 * round_off * g_scale}));
        if (!periodic) { // rotation invariance: no net torque about the origin (coordinates ~7)
            Eigen::Vector3d torque = Eigen::Vector3d::Zero();
            for (Eigen::Index v = 0; v < dofs / 3; ++v)
                torque += x.segment<3>(3 * v).cross(forces.col(v));
            CHECK_CLOSE(torque.norm(), 0.0, (Tolerance{0, 1e4 * round_off * g_scale}));
        }
    }
}

TEST_CASE("3D smooth contacts through a Lees-Edwards sheared boundary: images, forces, virial pressure")
{
    Rng rng(23);
    Eigen::VectorXd x;
    const double gamma = 0.37;
    const DpmSystem3d s = sheared_trio(rng, gamma, x);
    const double L = *s.box;
    const Eigen::Index dofs = x.size();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const double energy = interaction_energy3d(s, x, &g, &h);
    const std::vector<int> contacts = contact_counts3d(s, x);
    CHECK(contacts[2] > 0); // particle 2 touches only the sheared image of particle 0
    // A lattice vector of the sheared box, (gamma L, L, 0), maps particle 0 onto an image: U unchanged
    // (round-off of coordinates ~L); the plain (0, L, 0) does not (the check is not vacuous).
    const auto moved = [&](const Eigen::Vector3d& by) {
        Eigen::VectorXd y = x;
        for (int v = 0; v < s.particles[0].count; ++v)
            y.segment<3>(3 * v) += by;
        return interaction_energy3d(s, y, nullptr, nullptr);
    };
    CHECK_CLOSE(moved(Eigen::Vector3d(gamma * L, L, 0)), energy, (Tolerance{1e3 * round_off, 0}));
    CHECK(std::abs(moved(Eigen::Vector3d(0, L, 0)) - energy) > 0.1 * energy);
    check_against_central_differences([&](const Eigen::VectorXd& y, Eigen::VectorXd* gy,
                                          Eigen::MatrixXd* hy) { return interaction_energy3d(s, y, gy, hy); },
                                      x, g, h);
    // Virial pressure = -dU/dV under homogeneous dilation at fixed strain (tolerance as in the next test).
    const double V = std::pow(L, 3), e = 1e-5;
    const double dV = (std::pow(1 + e, 3) - std::pow(1 - e, 3)) * V;
    const auto dilated = [&](double f) {
        DpmSystem3d d = s;
        *d.box *= f;
        return interaction_energy3d(d, f * x, nullptr, nullptr);
    };
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    interaction_energy3d(s, x, nullptr, nullptr, &moment);
    CHECK_CLOSE(moment.trace() / (3 * V), -(dilated(1 + e) - dilated(1 - e)) / dV, (Tolerance{1e-7, 0}));
}

TEST_CASE("3D smooth contacts with two images of one particle in a small sheared box = open-space copies")
{
    // Two icosahedra (as in smooth_trio) 2.2 apart along y in a box of side 4.4 with Lees-Edwards strain
    // 0.02: particle 1 touches particle 0 directly and, through the boundary y = 0, at its sheared image
    // (-gamma L, -L, 0). The periodic energy must equal that of particle 0 with both copies of particle 1
    // in open space (the copies are 4.4 apart: no contact between them).
    Rng rng(31);
    const double gamma = 0.02, L = 4.4;
    DpmSystem3d s;
    s.interaction = InteractionKind::smooth;
    s.box = L;
    s.lees_edwards_strain = gamma;
    s.meshes.push_back(icosahedron_mesh());
    Eigen::VectorXd x;
    std::vector<Eigen::Matrix3Xd> shapes;
    for (int m = 0; m < 2; ++m) {
        Eigen::Matrix3Xd v = (random_rotation(rng) * s.meshes[0].vertices).colwise() +
                             Eigen::Vector3d(2.2, 1.1 + 2.2 * m, 2.2);
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.04 * rng.uniform(-1, 1);
        shapes.push_back(v);
        s.add_particle(0, v, 0.9, ShapeParameters3d{}, x);
    }
    DpmSystem3d open = s;
    open.box.reset();
    open.lees_edwards_strain = 0;
    Eigen::VectorXd y = x;
    open.add_particle(0, shapes[1].colwise() - Eigen::Vector3d(gamma * L, L, 0), 0.9, ShapeParameters3d{}, y);
    const double periodic = interaction_energy3d(s, x, nullptr, nullptr),
                 copies = interaction_energy3d(open, y, nullptr, nullptr);
    DpmSystem3d direct = open;
    direct.particles.pop_back();
    const double one_image = interaction_energy3d(direct, x, nullptr, nullptr);
    CHECK(one_image > 0);
    CHECK(copies - one_image > 0.1 * one_image); // the second image does touch
    // Summation order differs (round-off of terms of size k_c sigma^2).
    CHECK_CLOSE(periodic, copies, (Tolerance{1e3 * round_off, 0}));
}

TEST_CASE(
    "3D virial pressure with smooth contacts = -dU/dV under homogeneous dilation [DPM eq. (9.26) in 3D]")
{
    Rng rng(17);
    Eigen::VectorXd x;
    DpmSystem3d s = smooth_trio(rng, true, x);
    const Eigen::VectorXd reference = mesh_coordinates(s.meshes[0]);
    const ShapeParameters3d shell =
        model_shape3d(ShapeModel::shell, s.meshes[0], reference,
                      shape_parameter3d(mesh_surface_area(s.meshes[0], reference, 0),
                                        mesh_volume(s.meshes[0], reference, 0)),
                      1.0, Stiffness3d{});
    for (Particle3d& p : s.particles)
        p.shape = shell; // deformed shells: shape forces as well
    const double V = std::pow(*s.box, 3), e = 1e-5;
    const double dV = (std::pow(1 + e, 3) - std::pow(1 - e, 3)) * V;
    const auto dilated = [&](double f, bool contacts_only) {
        DpmSystem3d d = s;
        *d.box *= f;
        return contacts_only ? interaction_energy3d(d, f * x, nullptr, nullptr)
                             : total_energy3d(d, f * x, nullptr, nullptr);
    };
    Eigen::Matrix3d contacts = Eigen::Matrix3d::Zero();
    interaction_energy3d(s, x, nullptr, nullptr, &contacts);
    CHECK(contacts.trace() > 0); // overlapping: not vacuous
    // Central differences with e = 1e-5: truncation ~e^2 relative, round-off ~eps U/(e P V) ~1e-10; 1e-7
    // leaves a margin of 1000 (as for rough contacts, jamming3d.cpp).
    CHECK_CLOSE(contacts.trace() / (3 * V), -(dilated(1 + e, true) - dilated(1 - e, true)) / dV,
                (Tolerance{1e-7, 0}));
    CHECK_CLOSE(pressure3d(stress_tensor3d(s, x)), -(dilated(1 + e, false) - dilated(1 - e, false)) / dV,
                (Tolerance{1e-7, 0}));
}

TEST_CASE(
    "a particle pressed on a flat mesh: smooth energy independent of the contact point, rough corrugated")
{
    // Slab: top grid of 9 x 9 vertices 1 apart at z = 0.5 (thickness 1); probe: an icosahedron of
    // circumradius 2 with vertex 0 pointing down, its tip at height h = 0.4 above the top. sigma = 1: only
    // the tip is within sigma of the slab (the next ring is 2 (1 - 1/sqrt 5) = 1.106 higher).
    const double h = 0.4, sigma = 1.0, kc = 1.3, top = 0.5;
    DpmSystem3d s;
    s.kc = kc;
    s.meshes.push_back(slab_mesh(9, 1.0, 1.0));
    const TriangleMesh ico = vertex_down(icosahedron_mesh()); // as dpm.slide3d's slider
    s.meshes.push_back(ico);
    Eigen::VectorXd x;
    s.add_particle(0, s.meshes[0].vertices, sigma, ShapeParameters3d{}, x);
    const Eigen::Matrix3Xd probe = 2.0 * ico.vertices;
    s.add_particle(1, probe, sigma, ShapeParameters3d{}, x);
    const auto place = [&](double px, double py) { // tip above (px, py) of the top face
        const Eigen::Vector3d shift(px, py, top + h + 2.0);
        x.segment(3 * s.particles[1].first, 3 * ico.vertex_count()) = (probe.colwise() + shift).reshaped();
    };
    // Over a vertex, an edge (axis-parallel and diagonal), inside a triangle, and at random points of the
    // central squares: the tip's vertex-surface energy is 1/2 k_c/2 (sigma - h)^2 (eq. 9.5's 1/2).
    Rng rng(2);
    std::vector<Eigen::Vector2d> spots{{0, 0}, {0.5, 0}, {0, 0.5}, {0.5, 0.5}, {0.7, 0.2}, {0.2, 0.7}};
    for (int k = 0; k < 20; ++k)
        spots.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    s.interaction = InteractionKind::smooth;
    const double expected = 0.5 * 0.5 * kc * (sigma - h) * (sigma - h);
    for (const Eigen::Vector2d& spot : spots) {
        CAPTURE(spot.transpose());
        place(spot.x(), spot.y());
        // round-off: a handful of cancelling terms of size k_c sigma^2
        CHECK_CLOSE(smooth_vertex_surface_energy3d(s, 1, 0, x), expected,
                    (Tolerance{0, 100 * round_off * kc}));
    }
    // Validity: a tip pushed 0.2 below the top face has passed through it (NumericalError, not a silent
    // energy from the unsigned distance).
    const Eigen::Vector3d below(0.3, 0.2, top - 0.2 + 2.0);
    x.segment(3 * s.particles[1].first, 3 * ico.vertex_count()) = (probe.colwise() + below).reshaped();
    CHECK_THROWS_AS(smooth_vertex_surface_energy3d(s, 1, 0, x), NumericalError);
    // Rough (eq. 9.4): over a vertex only that vertex is closer than sigma (the next at sqrt(h^2 + 1));
    // over the centre of a square its four corners are at sqrt(h^2 + 1/2) = 0.812.
    s.interaction = InteractionKind::rough;
    place(0, 0);
    CHECK_CLOSE(interaction_energy3d(s, x, nullptr, nullptr), 0.5 * kc * (sigma - h) * (sigma - h),
                (Tolerance{1e3 * round_off, 0}));
    place(0.5, 0.5);
    const double r = std::sqrt(h * h + 0.5);
    CHECK_CLOSE(interaction_energy3d(s, x, nullptr, nullptr), 4 * 0.5 * kc * (sigma - r) * (sigma - r),
                (Tolerance{1e3 * round_off, 0}));
}

TEST_CASE("3D smooth contacts from the vertex list = every particle pair at every image, also where a vertex "
          "sees two images of one particle [DPM sec. 9.3.2]")
{
    // The trio in open space, in the box of side 6.6 and in the box sheared by 0.37; a vertex that touches
    // two images of one particle in a box of side 3.2, below twice the list's reach.
    Rng rng(41);
    std::vector<std::pair<DpmSystem3d, Eigen::VectorXd>> cases;
    for (const bool periodic : {false, true}) {
        Eigen::VectorXd x;
        DpmSystem3d s = smooth_trio(rng, periodic, x);
        cases.emplace_back(s, x);
    }
    {
        Eigen::VectorXd x;
        DpmSystem3d s = sheared_trio(rng, 0.37, x);
        cases.emplace_back(s, x);
    }
    {
        // A small icosahedron (circumradius 0.25) midway between two images of a unit one in a sheared box of
        // side 3.2: the gap between their surfaces is 1.2 - 1.4 wide, so the small particle's vertices are
        // within sigma_mb = 0.9 of both images.
        DpmSystem3d s;
        s.interaction = InteractionKind::smooth;
        s.box = 3.2;
        s.lees_edwards_strain = 0.02;
        s.meshes.push_back(icosahedron_mesh());
        Eigen::VectorXd x;
        const Eigen::Vector3d centre(1.0, 1.6, 1.6);
        s.add_particle(0, (random_rotation(rng) * s.meshes[0].vertices).colwise() + centre, 0.9,
                       ShapeParameters3d{}, x);
        s.add_particle(0,
                       (0.25 * random_rotation(rng) * s.meshes[0].vertices).colwise() +
                           (centre + Eigen::Vector3d(1.6, 0.1, 0)),
                       0.9, ShapeParameters3d{}, x);
        REQUIRE_FALSE(s.contacts.list(s, x)->one_image());
        int images_touched = 0;
        for (const auto& [vertex, particle] : touching_pairs3d(s, x))
            images_touched += vertex == s.particles[1].first && particle == 0;
        REQUIRE(images_touched == 2); // the small particle's first vertex touches both images
        cases.emplace_back(s, x);
    }
    for (std::size_t c = 0; c < cases.size(); ++c) {
        CAPTURE(c);
        const auto& [s, x] = cases[c];
        const double energy = interaction_energy3d(s, x, nullptr, nullptr);
        CHECK(energy > 0);
        // Sums of up to a few hundred terms of size k_c sigma^2 in another order.
        CHECK_CLOSE(energy, smooth_energy_over_all_images(s, x), (Tolerance{1e3 * round_off, 0}));
    }
}

TEST_CASE("3D smooth contacts: results do not depend on when the vertex list was built (bit for bit)")
{
    for (const double gamma : {0.0, 0.37}) {
        CAPTURE(gamma);
        Rng rng(43);
        Eigen::VectorXd start;
        DpmSystem3d s = sheared_trio(rng, gamma, start);
        interaction_energy3d(s, start, nullptr, nullptr); // the list is built at `start`
        const double skin = s.contacts.list(s, start)->skin();
        // Each vertex moves less than skin/2 in the unsheared coordinates: (1 + gamma) sqrt(3) 0.15 skin.
        Eigen::VectorXd moved = start;
        for (Eigen::Index k = 0; k < moved.size(); ++k)
            moved(k) += 0.15 * skin * rng.uniform(-1, 1);
        REQUIRE(interaction_energy3d(s, moved, nullptr, nullptr) !=
                interaction_energy3d(s, start, nullptr, nullptr)); // the motion matters
        check_same_with_fresh_list3d(s, moved);
    }
}

TEST_CASE("3D vertex list: switching rough to smooth contacts rebuilds it with the smooth reach; a box "
          "below the reach is a NumericalError")
{
    Rng rng(47);
    Eigen::VectorXd x;
    DpmSystem3d s = smooth_trio(rng, true, x);
    s.interaction = InteractionKind::rough;
    const double rough_range = s.contacts.list(s, x)->contact_range();
    CHECK(rough_range == 0.9); // sigma_max
    s.interaction = InteractionKind::smooth;
    const double smooth_range = s.contacts.list(s, x)->contact_range();
    CHECK(s.contacts.builds() == 2);
    CHECK(smooth_range > rough_range + 1.05 / std::sqrt(3.0)); // plus the longest edge over sqrt 3
    // The smooth reach (about 1.85 here) must stay below the box side.
    *s.box = 0.95 * smooth_range;
    CHECK_THROWS_AS(interaction_energy3d(s, x, nullptr, nullptr), NumericalError);
}
