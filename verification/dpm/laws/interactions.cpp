// DPM section 9.3.2: rough (eqs. 9.3-9.4) and smooth (eqs. 9.5-9.9) repulsion. Forces are minus the
// gradient and the Hessian the derivative of the forces, for every term (finite differences on random
// overlapping configurations); the smooth potential and its forces are continuous across the strip
// boundary at a concave corner, where U^edge alone jumps (Fig. 9.7d); closed forms of single contacts.
#include "dpm/laws/interactions.hpp"
#include "core/rng.hpp"
#include "dpm/system/system.hpp"
#include "support/derivatives.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_against_central_differences;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

const double pi = std::numbers::pi;

// Two or three overlapping, randomly deformed polygons (no shape energy: interactions only).
DpmSystem random_overlapping(InteractionKind kind, Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = kind;
    s.kc = rng.uniform(0.5, 2.0);
    const int count = 2 + static_cast<int>(rng.uniform(0, 2));
    for (int m = 0; m < count; ++m) {
        const int n = 5 + static_cast<int>(rng.uniform(0, 6));
        Eigen::Matrix2Xd v =
            regular_polygon(n, 1.0, Eigen::Vector2d(1.6 * m, rng.uniform(-0.3, 0.3)), rng.uniform(0, 2 * pi));
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.12 * rng.uniform(-1, 1); // seeded (not std::rand: independent of test order)
        s.add_particle(v, rng.uniform(0.4, 0.9), ShapeParameters{}, x);
    }
    return s;
}

void check_derivatives(const DpmSystem& s, const Eigen::VectorXd& x, unsigned smooth_terms)
{
    const Eigen::Index dofs = x.size();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(dofs, dofs);
    const double energy = interaction_energy(s, x, &g, &h, smooth_terms);
    CHECK_CLOSE(interaction_energy(s, x, nullptr, nullptr, smooth_terms), energy,
                (Tolerance{10 * round_off, 0}));
    check_against_central_differences(
        [&](const Eigen::VectorXd& y, Eigen::VectorXd* gy, Eigen::MatrixXd* hy) {
            return interaction_energy(s, y, gy, hy, smooth_terms);
        },
        x, g, h);
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff());
    // Interactions are internal forces: they sum to zero (Newton's third law).
    CHECK_CLOSE(g.reshaped(2, dofs / 2).rowwise().sum().norm(), 0.0,
                (Tolerance{0, 1e3 * round_off * g_scale}));
}

// A single vertex (a disk particle, no edges) at p against particle beta; sigma_mu_beta = 1.
struct VertexAgainstParticle
{
    DpmSystem system;
    Eigen::VectorXd x;
    VertexAgainstParticle(const Eigen::Matrix2Xd& beta, const Eigen::Vector2d& p)
    {
        system.interaction = InteractionKind::smooth;
        system.kc = 1.0;
        system.add_particle(beta, 1.0, ShapeParameters{}, x);
        Eigen::Matrix2Xd vertex(2, 1);
        vertex.col(0) = p;
        system.add_particle(vertex, 1.0, ShapeParameters{}, x);
    }
    // Energy of the selected smooth terms and the force on the lone vertex.
    std::pair<double, Eigen::Vector2d> at(const Eigen::Vector2d& p, unsigned terms)
    {
        x.tail<2>() = p;
        Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
        const double u = interaction_energy(system, x, &g, nullptr, terms);
        return {u, -g.tail<2>()};
    }
};

} // namespace

TEST_CASE(
    "rough and smooth interactions: forces = -grad U, Hessian = d(grad U), every term [DPM eqs. (9.3)-(9.9)]")
{
    Rng rng(99);
    const std::pair<unsigned, const char*> smooth_terms[] = {{edge_smooth, "edge (9.6)"},
                                                             {concave_smooth, "concave (9.8)"},
                                                             {convex_smooth, "convex (9.9)"},
                                                             {all_smooth, "all"}};
    int contacts_seen = 0;
    for (int sample = 0; sample < 12; ++sample) {
        Eigen::VectorXd x;
        const DpmSystem rough = random_overlapping(InteractionKind::rough, rng, x);
        CAPTURE(sample);
        check_derivatives(rough, x, all_smooth);
        DpmSystem smooth = rough;
        smooth.interaction = InteractionKind::smooth;
        for (const auto& [terms, name] : smooth_terms) {
            CAPTURE(name);
            check_derivatives(smooth, x, terms);
        }
        contacts_seen += interaction_energy(rough, x, nullptr, nullptr) > 0;
    }
    CHECK(contacts_seen >= 10); // the samples do overlap: the checks are not vacuous
}

TEST_CASE("rough contact: U = k_c/2 (sigma_mb - r)^2 with sigma_mb = (sigma_mu + sigma_beta)/2, central "
          "force [DPM eq. (9.4)]")
{
    Eigen::VectorXd x;
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.kc = 3.0;
    Eigen::Matrix2Xd a(2, 1), b(2, 1);
    a.col(0) = Eigen::Vector2d(0.1, 0.2);
    b.col(0) = Eigen::Vector2d(0.1 + 0.6, 0.2 + 0.8); // r = 1
    s.add_particle(a, 1.0, {}, x);
    s.add_particle(b, 1.4, {}, x); // sigma_mb = 1.2
    Eigen::VectorXd g = Eigen::VectorXd::Zero(4);
    const Tolerance exact{100 * round_off, 100 * round_off};
    CHECK_CLOSE(interaction_energy(s, x, &g, nullptr), 0.5 * 3.0 * 0.2 * 0.2, exact);
    // Force on b = k_c (sigma - r) along (r_b - r_a)/r.
    CHECK_CLOSE(-g(2), 3.0 * 0.2 * 0.6, exact);
    CHECK_CLOSE(-g(3), 3.0 * 0.2 * 0.8, exact);
    // Beyond sigma_mb: no interaction.
    x.tail<2>() = Eigen::Vector2d(0.1, 0.2 + 1.2 + 1e-12);
    CHECK(interaction_energy(s, x, nullptr, nullptr) == 0.0);
}

TEST_CASE("smooth vertex-edge contact: U = (1/2) k_c/2 (sigma - d)^2 with d the perpendicular distance [DPM "
          "eqs. (9.5)-(9.7)]")
{
    // Unit square, CCW; the vertex 0.3 above the middle of the top edge, sigma_mb = 1: d = 0.3.
    Eigen::Matrix2Xd square(2, 4);
    square << 0, 1, 1, 0, 0, 0, 1, 1;
    VertexAgainstParticle v(square, Eigen::Vector2d(0.5, 1.3));
    const auto [u, f] = v.at(Eigen::Vector2d(0.5, 1.3), all_smooth);
    const Tolerance exact{100 * round_off, 100 * round_off};
    CHECK_CLOSE(u, 0.5 * 0.5 * 0.7 * 0.7, exact); // 1/2 of eq. (9.5) (decision dpm-smooth-half)
    CHECK_CLOSE(f.x(), 0.0, exact);
    CHECK_CLOSE(f.y(), 0.5 * 0.7, exact);
    // Around a convex corner the potential is the vertex-vertex one (9.9): r = 0.5 from (1, 1).
    const Eigen::Vector2d corner(1, 1), q = corner + 0.5 * Eigen::Vector2d(std::cos(0.7), std::sin(0.7));
    CHECK_CLOSE(v.at(q, all_smooth).first, 0.5 * 0.5 * 0.5 * 0.5, exact);
}

TEST_CASE("smooth potential and forces are continuous across a concave corner; U^edge alone jumps [DPM Fig. "
          "9.7(d), eq. (9.8)]")
{
    // Particle beta: a block with a V notch whose exterior (wedge) angle is 120 deg, i.e. a concave
    // turning angle of 60 deg (between 0 and pi/2). The lone vertex slides parallel to edge C->D at 0.3
    // from it, inside the wedge, and enters the strip of edge D->E at t = 0.3 sqrt(3) where |p - D| = 0.6
    // < 1.
    const double s60 = std::sqrt(3.0);
    Eigen::Matrix2Xd beta(2, 5);
    beta << -3, 3, s60, 0, -s60, -3, -3, 1, 0, 1;
    const Eigen::Vector2d along(s60 / 2, 0.5), normal(-0.5, s60 / 2);
    const auto path = [&](double t) {
        Eigen::Vector2d p = t * along + 0.3 * normal;
        return p;
    };
    const double t_cross = 0.3 * s60, eps = 1e-9; // p . (E - D) = 0
    VertexAgainstParticle v(beta, path(0.0));
    const auto before = v.at(path(t_cross - eps), all_smooth), after = v.at(path(t_cross + eps), all_smooth);
    // Lipschitz continuity over a step of 2e-9 along the path: |dU| <= |F| 2e-9 ~ 1e-9, |dF| <= |U''| 2e-9.
    CHECK_CLOSE(after.first, before.first, (Tolerance{0, 1e-8}));
    CHECK_CLOSE((after.second - before.second).norm(), 0.0, (Tolerance{0, 1e-7}));
    // Without the concave term the edge potential jumps (1e-6: the 2e-9 step along the path) by (1/2) k_c/2
    // (sigma - r)^2 with r = |p - D| = 0.6.
    const auto edge_before = v.at(path(t_cross - eps), edge_smooth),
               edge_after = v.at(path(t_cross + eps), edge_smooth);
    const double r = path(t_cross).norm();
    CHECK_CLOSE(r, 0.6, (Tolerance{1e-12, 0}));
    CHECK_CLOSE(edge_before.first - edge_after.first, 0.25 * (1 - r) * (1 - r),
                (Tolerance{1e-6, 0})); // leaves the strip
    // ... and so does its force, by (1/2) k_c (sigma - r) along the normal of edge D->E.
    CHECK_CLOSE((edge_after.second - edge_before.second).norm(), 0.5 * (1 - r), (Tolerance{1e-6, 0}));
}

TEST_CASE("smooth potential is continuous around convex corners (edge <-> vertex hand-over) [DPM eqs. (9.6), "
          "(9.9)]")
{
    Eigen::Matrix2Xd square(2, 4);
    square << 0, 1, 1, 0, 0, 0, 1, 1;
    VertexAgainstParticle v(square, Eigen::Vector2d(2, 2));
    // Circle of radius 0.6 around the corner (1, 1): the strip boundaries are at angles 0 and pi/2.
    for (double boundary : {0.0, pi / 2}) {
        const auto point = [&](double angle) {
            return Eigen::Vector2d(1 + 0.6 * std::cos(angle), 1 + 0.6 * std::sin(angle));
        };
        const auto a = v.at(point(boundary - 1e-9), all_smooth), b = v.at(point(boundary + 1e-9), all_smooth);
        CHECK_CLOSE(a.first, b.first, (Tolerance{0, 1e-8}));
        CHECK_CLOSE((a.second - b.second).norm(), 0.0, (Tolerance{0, 1e-7}));
        CHECK(a.first > 0);
    }
}
