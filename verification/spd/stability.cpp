// Stability of the explicit scheme (SPD section 2.4, decision spd-stability-limit): the largest stable time
// step of the free shell is dt_c = sqrt(m/k_max); in compression it is set by the critically damped wall
// contact, 2 (sqrt(2) - 1) sqrt(m/k_n) = 0.828 dt_c; a larger dt stops the run with exit 3 naming the limit.
#include "core/errors.hpp"
#include "spd/ring.hpp"
#include "spd/time_step_limits.hpp"
#include "support/run_softgrain.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <string>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::Tolerance;

namespace {
// Largest kinetic energy over `steps` undamped steps of a free ring (N = 32) perturbed by 1e-6 R, or infinity
// if the state became non-finite.
double free_ring_kinetic_energy_max(double dt_factor, int steps)
{
    RingSetup setup;
    setup.nodes = 32;
    ShellModel model;
    add_ring(model, setup, 0.0);
    for (int i = 0; i < setup.nodes; ++i)
        model.set_vertex(i, model.vertex(i) + 1e-6 * Vec2(std::sin(7.3 * i), std::cos(3.1 * i)));
    model.compute_forces(0.0);
    const double dt = dt_factor * critical_time_step(model);
    double K = 0;
    try {
        for (int n = 0; n < steps; ++n) {
            model.step(dt, 0.0);
            K = std::max(K, model.kinetic_energy());
        }
    } catch (const NumericalError&) {
        return INFINITY;
    }
    return K;
}

// Largest dt/dt_c (bisection to 0.002) at which a ring squeezed to `strain` between the walls, each vertex
// then pushed by 1e-6 R towards the bottom wall, relaxes again (criterion 1e-6 EI/R^2 within 2e5 steps). The
// push is small enough for the linear stability of the state: no contact opens or closes (the limit is the
// same at 1e-8 R; at 1e-4 R contacts at the edges of the flat contact switch and the limit drops to 0.786
// at eps = 0.4, N = 32, decision spd-stability-limit).
double measured_compression_limit(int nodes, double strain)
{
    RingSetup setup;
    setup.nodes = nodes;
    RingBetweenWalls w = ring_between_walls(setup);
    const double dt_c = critical_time_step(w.model), dt0 = 0.5 * dt_c, damping = ring_damping(setup);
    const double push = 1e-6 * setup.radius;
    const double tolerance = 1e-6 * ring_scales(setup).flexural_rigidity / (setup.radius * setup.radius);
    const int steps = 20000;
    const double speed = strain * setup.radius / (steps * dt0);
    w.model.set_velocity(w.top_wall, Vec2(0, -speed));
    w.model.set_velocity(w.bottom_wall, Vec2(0, speed));
    for (int n = 0; n < steps; ++n)
        w.model.step(dt0, damping);
    w.model.set_velocity(w.top_wall, Vec2::Zero());
    w.model.set_velocity(w.bottom_wall, Vec2::Zero());
    relax(w.model, dt0, damping, tolerance, 2'000'000);
    double stable = 0.5, unstable = 1.2;
    while (unstable - stable > 0.002) {
        const double factor = 0.5 * (stable + unstable);
        ShellModel m = w.model;
        for (int i = 0; i < nodes; ++i)
            m.set_vertex(i, m.vertex(i) + Vec2(0, -push));
        bool relaxed = true;
        try {
            relax(m, factor * dt_c, damping, tolerance, 200'000);
        } catch (const NumericalError&) {
            relaxed = false;
        }
        (relaxed ? stable : unstable) = factor;
    }
    return stable;
}

// Two rings of the compaction (16 nodes, h = 0.1 R) touching vertex to vertex on the x axis (vertex 0 of
// the first against vertex 8 of the second), pressed together by F* on each ring, every y component frozen
// (a corner-to-corner contact is otherwise unstable to sliding), relaxed at a small dt with the contact law
// of the assemblies (k_n = k_s, c_n = 2 sqrt(m k_n)) and the global damping 2 m omega_2.
struct VertexPair
{
    RingSetup setup;
    ShellModel model;
    double damping = 0, tolerance = 0;
};

VertexPair vertex_pair()
{
    VertexPair p;
    p.setup.nodes = 16;
    p.setup.material.h = 0.1;
    const RingScales sc = ring_scales(p.setup);
    const double R = p.setup.radius, r = sc.radius_vertex, k_n = sc.laws.k_s;
    add_ring(p.model, p.setup, 0.0);
    const int second = add_ring(p.model, p.setup, 0.0);
    p.model.translate(second, Vec2(2 * R + 2 * r, 0));
    p.model.set_contact_law({k_n, 0.0, 0.0, 2 * std::sqrt(p.setup.vertex_mass * k_n)});
    const double F = sc.characteristic.F_star / p.setup.nodes;
    for (int i = 0; i < p.model.vertices(); ++i) {
        p.model.freeze(i, 1);
        p.model.set_applied_force(i, Vec2(i < p.setup.nodes ? F : -F, 0));
    }
    p.damping = ring_damping(p.setup);
    p.tolerance = 1e-4 * sc.characteristic.F_star;
    relax(p.model, 0.1 * critical_time_step(p.model), p.damping, p.tolerance, 2'000'000);
    return p;
}

// The relaxed pair with its contact vertices pushed 1e-4 R towards each other.
ShellModel pushed_together(const VertexPair& pair)
{
    ShellModel m = pair.model;
    const double push = 1e-4 * pair.setup.radius;
    m.set_vertex(0, m.vertex(0) + Vec2(push, 0));
    m.set_vertex(24, m.vertex(24) - Vec2(push, 0));
    return m;
}

// Whether the pushed pair relaxes again at dt/dt_c = `factor` (criterion 1e-4 F* within 2e5 steps).
bool vertex_pair_relaxes(const VertexPair& pair, double factor)
{
    ShellModel m = pushed_together(pair);
    try {
        relax(m, factor * critical_time_step(m), pair.damping, pair.tolerance, 200'000);
    } catch (const NumericalError&) {
        return false;
    }
    return true;
}
} // namespace

TEST_CASE("free shell: velocity Verlet is stable up to dt_c = sqrt(m/k_s) and not beyond [SPD section 2.4]")
{
    // The zig-zag stretch mode of the chain has omega^2 = 4 k_s/m: the limit 2/omega is dt_c exactly.
    CHECK(free_ring_kinetic_energy_max(0.99, 20000) < 1e-6);       // stays at the perturbation's level, 1e-7
    CHECK(free_ring_kinetic_energy_max(1.01, 20000) > 1e3 * 1e-6); // grows by (1.33)^steps: blow-up
}

TEST_CASE("a blow-up names the step, the first non-finite vertex and its particle [issue 4, reliability]")
{
    // Two rings; the second (particle 1, vertices 32-63) is perturbed and stepped above dt_c: it blows up
    // first, while the unperturbed first ring stays exactly at rest.
    RingSetup setup;
    setup.nodes = 32;
    ShellModel model;
    add_ring(model, setup, 0.0);
    const int second = add_ring(model, setup, 0.0);
    model.translate(second, Vec2(3 * setup.radius, 0));
    for (int i = 32; i < 64; ++i)
        model.set_vertex(i, model.vertex(i) + 1e-6 * Vec2(std::sin(7.3 * i), std::cos(3.1 * i)));
    model.compute_forces(0.0);
    const double dt = 1.2 * critical_time_step(model);
    std::string message;
    try {
        for (int n = 0; n < 1'000'000; ++n)
            model.step(dt, 0.0);
    } catch (const NumericalError& e) {
        message = e.what();
        CHECK(e.step > 0);
    }
    CHECK(message.find("of particle 1 first") != std::string::npos);
    CHECK(message.find("dt/dt_c = 1.2") != std::string::npos);
}

TEST_CASE("an energy blow-up in contact stops when a vertex moves farther than its contact radius in one "
          "step, naming it, before the state is non-finite [issue 4, reliability]")
{
    // A ring squeezed between the walls and stepped at 1.1 times the damped-contact limit
    // (decision spd-stability-limit): the contact chatter grows geometrically.
    RingSetup setup;
    setup.nodes = 32;
    RingBetweenWalls w = ring_between_walls(setup);
    for (int i = 0; i < setup.nodes; ++i) // pressed 1e-3 R into the bottom wall
        w.model.set_vertex(i, w.model.vertex(i) + Vec2(0, -1e-3 * setup.radius));
    w.model.compute_forces(0.0);
    const double dt = 1.1 * stable_time_step(w.model);
    NumericalError caught("", 0, "");
    try {
        for (int n = 0; n < 100'000; ++n)
            w.model.step(dt, 0.0);
    } catch (const NumericalError& e) {
        caught = e;
    }
    const std::string message = caught.what();
    CAPTURE(message);
    CHECK(caught.quantity == "vertex step length");
    CHECK(std::string(caught.what()).find("of particle " + std::to_string(w.ring) + " moved") !=
          std::string::npos);
    CHECK(caught.step > 1);
}

TEST_CASE(
    "ring between walls: the largest stable dt lies between the damped-contact limit 2 (sqrt 2 - 1) "
    "dt_c and the same limit with the shell's stiffness added to the contact's [SPD section 2.4, decision "
    "spd-stability-limit]")
{
    // Velocity Verlet with the damping c applied with the half-step velocity is stable for
    // h^2 omega^2 + 2 h gamma < 4 (omega^2 = k/m, gamma = c/m); c = c_n = 2 sqrt(m k_n) on a contact vertex.
    const auto damped_limit = [](double omega2, double gamma) {
        return (std::sqrt(gamma * gamma + 4 * omega2) - gamma) / omega2;
    };
    for (const auto& [nodes, strain] : {std::pair{32, 0.2}, {32, 0.4}, {128, 0.4}}) {
        CAPTURE(nodes);
        CAPTURE(strain);
        RingSetup setup;
        setup.nodes = nodes;
        const RingBetweenWalls w = ring_between_walls(setup);
        const ShellLaws laws = ring_scales(setup).laws;
        const double dt_c = critical_time_step(w.model),
                     k_n = laws.k_s; // k_n = k_s (decision spd-ring-walls)
        const double gamma = 2 * std::sqrt(k_n / setup.vertex_mass) * dt_c; // in units of 1/dt_c
        const double predicted = stable_time_step(w.model) / dt_c;
        CHECK_CLOSE(predicted, damped_limit(k_n / laws.k_s, gamma), (Tolerance{1e-12, 0}));
        CHECK_CLOSE(predicted, 2 * (std::sqrt(2.0) - 1), (Tolerance{1e-12, 0}));
        // The largest eigenvalue of the stiffness seen by the normal motion of a contact vertex is at least
        // k_n (its diagonal) and at most its Gershgorin row sum: k_n, the zig-zag bending 16 k_b/l0^2 (hinge
        // pattern 1 -4 6 -4 1), and the stretch of its two elements, tilted from the wall by less than the
        // free ring's turning angle 2 pi/N (the elastica's curvature vanishes at the edge of a flat contact),
        // 2 k_s sin^2(2 pi/N). The limit lies between the two damped limits (0.818 for N = 32, 0.803 for
        // N = 128); the bisection finds a stable factor within 0.002 below it.
        const double l0 = ring_scales(setup).l0, tilt = 2 * M_PI / nodes;
        const double k_bound = k_n + 16 * laws.k_b / (l0 * l0) + 2 * laws.k_s * std::pow(std::sin(tilt), 2);
        const double lower = damped_limit(k_bound / laws.k_s, gamma);
        const double measured = measured_compression_limit(nodes, strain);
        MESSAGE("N = ", nodes, ", eps = ", strain, ": limit ", measured, " dt_c, between ", lower, " and ",
                predicted);
        CHECK(measured <= predicted);
        CHECK(measured >= lower - 0.002);
    }
}

TEST_CASE("a time step above the stability limit stops the run with exit 3 naming the limit [decision "
          "spd-stability-limit]")
{
    RingSetup setup;
    setup.nodes = 32;
    setup.dt_factor = 0.9;
    CHECK_THROWS_WITH_AS(ring_compression(setup, 0.1, 0.05, false, 1e-4, [](double) {}),
                         doctest::Contains("above the stability limit"), NumericalError);
    const auto [exit_code, output] =
        verification::run_softgrain("run spd.ring_compression --set dt_factor=0.9 --set nodes=32 --out "
                                    "/tmp/softgrain-spd-stability --quiet");
    CHECK(exit_code == exit_numerical_failure);
    CAPTURE(output);
    CHECK(output.find("0.828") != std::string::npos); // the limit, in units of dt_c
}

TEST_CASE("a vertex pressed through a wall stops the run with exit 3 instead of tunnelling [SPD section 2.3, "
          "eq. (6)]")
{
    // Incompressible ring of 24 nodes at eps = 0.35: the wall force (about 1000 F*) on few contact vertices
    // exceeds k_n r per vertex; the overlap would pass r_i + r_j and the vertex cross the wall. At N = 32 the
    // same load is shared by more vertices and the run completes.
    RingSetup setup;
    setup.nodes = 24;
    setup.eta = INFINITY;
    CHECK_THROWS_WITH_AS(ring_compression(setup, 0.35, 0.05, false, 1e-4, [](double) {}),
                         doctest::Contains("contact overlap"), NumericalError);
    setup.nodes = 32;
    CHECK_NOTHROW(ring_compression(setup, 0.35, 0.05, false, 1e-4, [](double) {}));
}

TEST_CASE("two rings touching vertex to vertex: the largest stable dt is the vertex-pair limit (sqrt 5 - 2) "
          "dt_c; the former compaction step 0.25 dt_c flips the pair forever [decision "
          "spd-vertex-pair-stability]")
{
    const VertexPair pair = vertex_pair();
    const double predicted = stable_time_step(pair.model) / critical_time_step(pair.model);
    // k_n = k_s = k_max: omega^2 = 4 k_n/m, gamma = 8 sqrt(k_n/m), h^2 4 + 16 h = 4.
    CHECK_CLOSE(predicted, std::sqrt(5.0) - 2, (Tolerance{1e-12, 0}));
    double stable = 0.15, unstable = 0.35; // bisection to 0.002
    while (unstable - stable > 0.002) {
        const double factor = 0.5 * (stable + unstable);
        (vertex_pair_relaxes(pair, factor) ? stable : unstable) = factor;
    }
    MESSAGE("measured vertex-pair limit ", stable, " dt_c, predicted ", predicted);
    // The stretch springs of the two contact vertices (elements tilted 11.25 degrees from the normal's
    // perpendicular) add 2 k_s sin^2(11.25) = 0.08 k_s to the pair's 4 k_n: the limit is lower by about 0.5%
    // (measured 0.2344 against 0.2361), never above the prediction; 1% also covers the bisection's 0.002.
    CHECK(stable <= predicted);
    CHECK_CLOSE(stable, predicted, (Tolerance{0.01, 0}));
    CHECK_FALSE(vertex_pair_relaxes(pair, 0.25)); // the 500-ring deposition's failure
    CHECK(vertex_pair_relaxes(pair, 0.2));        // the compaction's step now
}

TEST_CASE("a relaxation that fails names the vertex holding the residual and tells a period-2 oscillation "
          "from a slow approach to rest [issue 4, reliability]")
{
    const VertexPair pair = vertex_pair();
    ShellModel flipping = pushed_together(pair);
    const double dt_c = critical_time_step(flipping);
    std::string message;
    try {
        relax(flipping, 0.25 * dt_c, pair.damping, pair.tolerance, 200'000);
    } catch (const NumericalError& e) {
        message = e.what();
    }
    CAPTURE(message);
    // One of the two contact vertices (the pair is symmetric: which one is a matter of round-off).
    CHECK((message.find("on vertex 0 of particle 0") != std::string::npos ||
           message.find("on vertex 24 of particle 1") != std::string::npos));
    CHECK(message.find("reverses at every step") != std::string::npos);
    ShellModel slow = pushed_together(pair); // stable, but 16 steps are too few to come to rest
    CHECK_THROWS_WITH_AS(relax(slow, 0.2 * dt_c, pair.damping, pair.tolerance, 16),
                         doctest::Contains("damping too weak or too strong"), NumericalError);
}
