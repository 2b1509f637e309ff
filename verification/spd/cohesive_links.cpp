// Cohesive links of SPD section 6 (lib/spd/cohesive_link.hpp) and the tissue built from them
// (lib/spd/tissue.hpp): the yield function of eq. (39) and its zeta = 0 curve (Fig. 31), the link forces as
// minus the gradient of the link energy, Newton's third law, irreversible breaking into a Coulomb contact
// (eqs. (6)-(7), mu = 0.3), the Laguerre tessellation (a tiling, two links per interior interface) and the
// quasi-static balance of a small elastic tissue.
#include "core/rng.hpp"
#include "dpm/laws/local_derivatives.hpp"
#include "spd/cohesive_link.hpp"
#include "spd/time_step_limits.hpp"
#include "spd/tissue.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Geometry>
#include <omp.h>

#include <array>
#include <cmath>
#include <map>
#include <type_traits>
#include <vector>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {
CohesiveLaw paper_law()
{
    CohesiveLaw law; // alpha = 2 (section 6); f_t^0 != |f_n^0| so that the two thresholds are told apart
    law.k_n = 1e4;
    law.k_t = 0.1 * law.k_n; // decision spd-tissue-kt
    law.f_n0 = -2.0;
    law.f_t0 = 3.0;
    return law;
}

// A link across an interface of length 1 along x between y = 0 (vertices a) and y = 0.04 (vertices b), in a
// rotated and shifted frame.
struct FourPoints
{
    Vec2 a, b, pa, pb;
};
FourPoints interface(double angle, const Vec2& shift)
{
    const Eigen::Rotation2Dd rot(angle);
    return {rot * Vec2(0, 0) + shift, rot * Vec2(0.01, 0.04) + shift, rot * Vec2(1, 0) + shift,
            rot * Vec2(0.99, 0.04) + shift};
}
CohesiveLink link_at_rest(const FourPoints& p)
{
    CohesiveLink link{0, 1, 2, 3};
    LinkKinematics k = link_kinematics(link, p.a, p.b, p.pa, p.pb);
    if (k.gap < 0) link.normal_sign = -1, k.gap = -k.gap;
    link.gap0 = k.gap;
    link.slip0 = k.slip;
    return link;
}
} // namespace

TEST_CASE(
    "yield function zeta = f_n/f_n^0 + |f_t/f_t^0|^2 - 1 and its zeta = 0 curve [SPD eq. (39), Fig. 31]")
{
    const CohesiveLaw law = paper_law();
    // On the curve f_n = f_n^0 (1 - (f_t/f_t^0)^2) zeta vanishes to round-off (a few operations on O(1)
    // terms).
    for (double f_t = -1.5 * law.f_t0; f_t <= 1.5 * law.f_t0; f_t += 0.125)
        CHECK_CLOSE(yield_function(yield_normal_force(f_t, law), f_t, law), 0.0,
                    (Tolerance{0, 8 * round_off}));
    // Closed form, independent of the library: zeta(f_n, f_t) at a few points.
    CHECK_CLOSE(yield_function(1.0, 1.5, law), 1.0 / -2.0 + 0.25 - 1.0, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(yield_function(-1.0, 0.0, law), -0.5, (Tolerance{4 * round_off, 0}));
    // Mode I only in tension: at f_t = 0 the link breaks at f_n = f_n^0 < 0 and never in compression.
    CHECK(yield_function(law.f_n0, 0.0, law) >= 0);
    CHECK(yield_function(0.999 * law.f_n0, 0.0, law) < 0);
    for (double f_n = 0; f_n <= 1e3; f_n += 50)
        CHECK(yield_function(f_n, 0.0, law) < 0);
    // In compression (f_n > 0) only by shear, beyond |f_t| = f_t^0 sqrt(1 + f_n/|f_n^0|).
    for (double f_n : {0.5, 2.0, 10.0}) {
        const double f_t_break = law.f_t0 * std::sqrt(1 + f_n / std::abs(law.f_n0));
        CHECK_CLOSE(yield_function(f_n, f_t_break, law), 0.0, (Tolerance{0, 16 * round_off}));
        CHECK(yield_function(f_n, 0.999 * f_t_break, law) < 0);
        CHECK(yield_function(f_n, -1.001 * f_t_break, law) > 0);
    }
}

TEST_CASE("link forces are minus the gradient of k_n u_n^2/2 + k_t u_t^2/2 and sum to zero [SPD section 6]")
{
    const CohesiveLaw law = paper_law();
    Rng rng(11);
    for (int trial = 0; trial < 20; ++trial) {
        const FourPoints rest = interface(rng.uniform(-3, 3), Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5)));
        const CohesiveLink link = link_at_rest(rest);
        // A displaced configuration: 1e-2 of the gap on each vertex (opening, sliding and turning the frame).
        std::array<Vec2, 4> x = {rest.a, rest.b, rest.pa, rest.pb};
        for (Vec2& xi : x)
            xi += 4e-4 * Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1));
        const LinkForces F = link_forces(link, law, link_kinematics(link, x[0], x[1], x[2], x[3]));
        const std::array<Vec2, 4> forces = {F.a, F.b, F.partner_a, F.partner_b};
        // Central differences of the energy with step e: error O(e^2 W'''), W quadratic in u and u smooth in
        // x on the scale of the interface (1 m): relative error ~ e^2 = 1e-12 plus round-off W eps / e ~ 1e-9
        // of the force scale k_n * 4e-4 = 4 N.
        const double e = 1e-6, force_scale = law.k_n * 4e-4;
        for (int v = 0; v < 4; ++v)
            for (int c = 0; c < 2; ++c) {
                std::array<Vec2, 4> plus = x, minus = x;
                plus[v][c] += e;
                minus[v][c] -= e;
                const double dW = (link_energy<double>(link, law, plus[0], plus[1], plus[2], plus[3]) -
                                   link_energy<double>(link, law, minus[0], minus[1], minus[2], minus[3])) /
                                  (2 * e);
                CHECK_CLOSE(forces[v][c], -dW, (Tolerance{0, 1e-6 * force_scale}));
            }
        // Exact gradient of the same templated energy (forward-mode automatic differentiation): the
        // hand-written forces agree to round-off of sums of O(force_scale) terms divided by the interface
        // length (1 m).
        const auto energy = [&](const auto& q) {
            using Scalar = std::decay_t<decltype(q(0))>;
            using V = Eigen::Matrix<Scalar, 2, 1>;
            return link_energy<Scalar>(link, law, V(q(0), q(1)), V(q(2), q(3)), V(q(4), q(5)), V(q(6), q(7)));
        };
        Eigen::Matrix<double, 8, 1> q;
        q << x[0], x[1], x[2], x[3];
        const auto exact = dpm::local_gradient<8>(energy, q);
        for (int v = 0; v < 4; ++v)
            for (int c = 0; c < 2; ++c)
                CHECK_CLOSE(forces[v][c], -exact.gradient(2 * v + c),
                            (Tolerance{0, 1e3 * round_off * force_scale}));
        // Newton's third law and no net moment (W is invariant under translations and rotations): round-off
        // of sums of O(force_scale) terms.
        const Vec2 sum = F.a + F.b + F.partner_a + F.partner_b;
        CHECK_CLOSE(sum.norm(), 0.0, (Tolerance{0, 64 * round_off * force_scale}));
        const double moment = cross2<double>(x[0], F.a) + cross2<double>(x[1], F.b) +
                              cross2<double>(x[2], F.partner_a) + cross2<double>(x[3], F.partner_b);
        // The moment sums products of positions up to 8 m with forces: round-off relative to 8 m x
        // force_scale.
        CHECK_CLOSE(moment, 0.0, (Tolerance{0, 128 * round_off * 8 * force_scale}));
        // f_n and f_t are the forces of the linear laws: compression (closing) positive.
        const LinkKinematics k = link_kinematics(link, x[0], x[1], x[2], x[3]);
        CHECK_CLOSE(F.f_n, law.k_n * (link.gap0 - k.gap), (Tolerance{4 * round_off, 0}));
        CHECK_CLOSE(F.f_t, law.k_t * (k.slip - link.slip0), (Tolerance{4 * round_off, 0}));
    }
    // Pure opening: the side b of the interface moved by delta along n keeps the frame; f_n = -k_n delta
    // (tension), f_t = 0, the force on b points back to a.
    const FourPoints rest = interface(0.0, Vec2::Zero());
    const CohesiveLink link = link_at_rest(rest);
    const double delta = 1e-4;
    const LinkForces F = link_forces(
        link, law, link_kinematics(link, rest.a, rest.b + Vec2(0, delta), rest.pa, rest.pb + Vec2(0, delta)));
    CHECK_CLOSE(F.f_n, -law.k_n * delta, (Tolerance{64 * round_off * 0.04 / delta, 0})); // gap - gap0 cancels
    CHECK_CLOSE(F.f_t, 0.0, (Tolerance{0, 64 * round_off * law.k_t}));
    CHECK(F.b.y() < 0);
}

namespace {
// Two square cells of side 1 (8 vertices each, r = 0.02), the lower one clamped, the upper one shifted by 1/4
// along x and linked to it across their horizontal interface (gap 2r): a two-cell tissue.
struct TwoCells
{
    ShellModel model;
    int lower = 0, upper = 0;
};
TwoCells two_cells(double friction)
{
    TwoCells t;
    const double r = 0.02;
    const auto square = [&](double x0, double y0) {
        Points<2> v(2, 8);
        v << x0, x0 + 0.5, x0 + 1, x0 + 1, x0 + 1, x0 + 0.5, x0, x0, //
            y0, y0, y0, y0 + 0.5, y0 + 1, y0 + 1, y0 + 1, y0 + 0.5;
        return v;
    };
    Shell shell;
    shell.laws = calibrate({1e6, 0.3, 0.1, 0.1}, 0.5);
    shell.depth = 0.1;
    shell.radius = r;
    t.lower = t.model.add_shell(square(0, -1 - r), shell, 1.0);
    t.upper =
        t.model.add_shell(square(0.25, r), shell, 1.0); // offset: contacts inside elements, not at corners
    for (int i = 0; i < 8; ++i) {
        t.model.freeze(i, 0);
        t.model.freeze(i, 1);
    }
    // The interface: lower vertices 4 (1, -r) and 6 (0, -r); upper vertices 8 (0.25, r) and 10 (1.25, r).
    CohesiveLaw law;
    law.k_n = 1e4;
    law.k_t = 1e3;
    law.f_n0 = -5;
    law.f_t0 = 5;
    std::vector<CohesiveLink> links = {{6, 8, 4, 10}, {4, 10, 6, 8}};
    for (CohesiveLink& link : links) {
        const LinkKinematics k =
            link_kinematics(link, t.model.vertex(link.a), t.model.vertex(link.b),
                            t.model.vertex(link.partner_a), t.model.vertex(link.partner_b));
        link.normal_sign = k.gap < 0 ? -1 : 1;
        link.gap0 = std::abs(k.gap);
        link.slip0 = k.slip;
    }
    t.model.set_cohesive_links(links, law);
    t.model.set_contact_law({law.k_n, law.k_t, friction, 2 * std::sqrt(law.k_n)});
    return t;
}

void load_upper(TwoCells& t, const Vec2& total)
{
    const Shell& s = t.model.shells()[t.upper];
    for (int i = s.first; i < s.first + s.count; ++i)
        t.model.set_applied_force(i, total / s.count);
}
} // namespace

TEST_CASE(
    "a link breaks at f_n = f_n^0 in tension, never re-forms, and leaves a Coulomb contact [SPD section 6]")
{
    TwoCells t = two_cells(0.3);
    const double dt = 0.25 * critical_time_step(t.model);
    const double damping = 2 * std::sqrt(t.model.shells()[t.upper].laws.k_s); // critical for a k_s spring
    // A pull below the threshold (2 links, |f_n^0| = 5 N each): intact, each carries half the load at rest.
    load_upper(t, Vec2(0, 8.0));
    relax(t.model, dt, damping, 1e-7, 2'000'000);
    CHECK(t.model.broken_links() == 0);
    // Relaxed to 1e-7 N per dof: the residuals of the 16 free dof bound the error, 2e-6 N. The links carry
    // the load to the clamped cell (they share it unequally: the shifted cell is not mirror symmetric).
    double clamp = 0;
    for (int i = 0; i < 8; ++i)
        clamp += t.model.force(i).y();
    CHECK_CLOSE(clamp, 8.0, (Tolerance{0, 2e-6}));
    for (const CohesiveLink& link : t.model.links()) {
        CHECK(link.f_n < 0); // tension
        CHECK(yield_function(link.f_n, link.f_t, t.model.link_law()) < 0);
    }
    // Beyond it: both links break (no moment: they share the load) and the cell flies off.
    load_upper(t, Vec2(0, 10.5));
    for (int n = 0; n < 2000; ++n)
        t.model.step(dt, 0.0);
    CHECK(t.model.broken_links() == 2);
    for (const CohesiveLink& link : t.model.links()) // broken on reaching the yield surface of eq. (39)
        CHECK(yield_function(link.f_n, link.f_t, t.model.link_law()) >= 0);
    // Pushed back onto the lower cell, the links stay broken: only the contact law acts.
    load_upper(t, Vec2(0, -20.0));
    relax(t.model, dt, damping, 1e-7, 4'000'000);
    CHECK(t.model.broken_links() == 2);
    CHECK_CLOSE(t.model.contact_force_on(t.upper).y(), 20.0, (Tolerance{0, 2e-6})); // 16 dof at 1e-7 N
    // Stick: a tangential load 0.2 N below mu N = 6 N is carried by friction, the cell comes to rest.
    const double x_before = t.model.vertex(t.model.shells()[t.upper].first).x();
    load_upper(t, Vec2(4.0, -20.0));
    relax(t.model, dt, damping, 1e-7, 4'000'000);
    CHECK_CLOSE(t.model.contact_force_on(t.upper).x(), -4.0, (Tolerance{0, 2e-6}));
    const double stick_shift = t.model.vertex(t.model.shells()[t.upper].first).x() - x_before;
    CHECK(std::abs(stick_shift) < 4.0 / t.model.link_law().k_t); // elastic tangential spring only
    // Slide: above mu N the friction saturates at mu f_n on every contact and the cell accelerates.
    load_upper(t, Vec2(8.0, -20.0));
    for (int n = 0; n < 20000; ++n)
        t.model.step(dt, damping * 1e-3);
    const Vec2 F = t.model.contact_force_on(t.upper);
    CHECK_CLOSE(-F.x(), 0.3 * F.y(), (Tolerance{1e-9, 0})); // Coulomb clamp, exact up to round-off
    CHECK(t.model.velocity(t.model.shells()[t.upper].first).x() > 0.1);
    CHECK(t.model.broken_links() == 2);
}

TEST_CASE("Laguerre tessellation: the cells tile the box and every interior interface carries two links "
          "[SPD section 6, Fig. 30]")
{
    TissueSetup setup;
    setup.columns = 6;
    setup.rows = 5;
    setup.seed = 4;
    const Tissue tissue = build_tissue(setup);
    const Tessellation& t = tissue.tessellation;
    const double box = t.width * t.height;
    // voro++ cells (before merging corners) and our polygons (after) tile the box: sums of ~30 areas of
    // O(box/30), round-off a few hundred eps of the box area.
    CHECK_CLOSE(t.voronoi_area, box, (Tolerance{256 * round_off, 0}));
    CHECK_CLOSE(total_cell_area(t), box, (Tolerance{256 * round_off, 0}));
    // Two links per interior interface, each pair of neighbouring cells linked exactly twice.
    const ShellModel& model = tissue.model;
    CHECK(static_cast<int>(model.links().size()) == 2 * tissue.interfaces);
    std::vector<int> cell_of(static_cast<std::size_t>(model.vertices()));
    for (std::size_t c = 0; c < tissue.cells.size(); ++c) {
        const Shell& s = model.shells()[tissue.cells[c]];
        for (int i = s.first; i < s.first + s.count; ++i)
            cell_of[i] = static_cast<int>(c);
    }
    std::map<std::pair<int, int>, int> per_pair;
    for (const CohesiveLink& link : model.links()) {
        const int ci = cell_of[link.a], cj = cell_of[link.b];
        CHECK(ci != cj);
        ++per_pair[{std::min(ci, cj), std::max(ci, cj)}];
    }
    for (const auto& [pair, count] : per_pair)
        CHECK(count == 2);
    CHECK(static_cast<int>(per_pair.size()) == tissue.interfaces);
    // A hexagonal-like tissue: 3 interfaces per cell in the bulk, fewer at the boundary.
    CHECK(tissue.interfaces > static_cast<int>(2 * tissue.cells.size()));
    // The clamps: every bottom-row and top-row cell holds clamped vertices on y = r and y = H - r.
    for (int i : tissue.bottom)
        CHECK_CLOSE(model.vertex(i).y(), setup.vertex_radius, (Tolerance{0, 64 * round_off * t.height}));
    for (int i : tissue.top)
        CHECK_CLOSE(model.vertex(i).y(), t.height - setup.vertex_radius,
                    (Tolerance{0, 64 * round_off * t.height}));
}

TEST_CASE("a small elastic tissue under a small imposed strain carries the same force at both clamps "
          "[SPD section 6, quasi-static balance]")
{
    TissueSetup setup;
    setup.columns = 4;
    setup.rows = 4;
    setup.link_stiffness = 0.1;
    setup.cohesion = 1e3; // no link breaks
    Tissue tissue = build_tissue(setup);
    ShellModel& model = tissue.model;
    const double dt = 0.25 * critical_time_step(model);
    // Impose eps_h = 1e-3 by moving the top clamp, then relax at rest.
    for (int i : tissue.top)
        model.set_vertex(i, model.vertex(i) + Vec2(0, 1e-3 * tissue.height0));
    const double k_s = model.shells()[tissue.cells.front()].laws.k_s;
    const double tolerance = 1e-7 * k_s * 1e-3; // of the force of a wall spring stretched by the strain
    relax(model, dt, 0.02 * 2 * std::sqrt(k_s), tolerance, 5'000'000);
    const double top = top_clamp_force(tissue), bottom = bottom_clamp_force(tissue);
    MESSAGE("clamp forces: top " << top << " N, bottom " << bottom << " N, bound " << tolerance
                                 << " N per dof");
    CHECK(top > 1e3 * model.vertices() * tolerance); // the check below is sharp against the load
    // Global balance: F_top - F_bottom is the sum of the residual forces on the free vertices, each below the
    // relaxation tolerance per dof.
    const int free_vertices = model.vertices() - static_cast<int>(tissue.top.size() + tissue.bottom.size());
    CHECK_CLOSE(top, bottom, (Tolerance{0, free_vertices * tolerance}));
    CHECK(model.broken_links() == 0);
}

TEST_CASE(
    "tissue forces with links do not depend on the number of OpenMP threads [decision spd-contact-detection]")
{
    TissueSetup setup;
    setup.columns = 12;
    setup.rows = 12;
    setup.edge_segments = 3; // above the 2000 vertices that open the parallel region
    setup.link_stiffness = 0.1;
    const int threads_before = omp_get_max_threads();
    std::vector<Eigen::VectorXd> forces;
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        Tissue tissue = build_tissue(setup);
        REQUIRE(tissue.model.vertices() > 2000);
        for (int i : tissue.top)
            tissue.model.set_vertex_velocity(i, Vec2(0, 1.0));
        const double dt = 0.25 * critical_time_step(tissue.model);
        for (int n = 0; n < 50; ++n)
            tissue.model.step(dt, 0.0);
        Eigen::VectorXd f(2 * tissue.model.vertices());
        for (int i = 0; i < tissue.model.vertices(); ++i)
            f.segment<2>(2 * i) = tissue.model.force(i);
        forces.push_back(f);
    }
    omp_set_num_threads(threads_before);
    CHECK((forces[0].array() == forces[1].array()).all()); // bit for bit
}
