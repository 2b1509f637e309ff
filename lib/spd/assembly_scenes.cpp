// Scenes of SPD assemblies (Trivino et al., section 5): spd.bench.
#include "core/errors.hpp"
#include "core/output.hpp"
#include "core/rng.hpp"
#include "spd/assembly.hpp"
#include "spd/spd_scenes.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <numbers>

namespace softgrain {

namespace {
using namespace spd;

// spd.bench: `particles` elastic rings (eta = 0) of `nodes` vertices, touching on a square lattice in a box,
// each launched with a random rigid velocity of 0.02 r per time step (r the vertex radius), `steps`
// undamped-in-the-bulk velocity-Verlet steps (contact damping only): rings collide, bend and rearrange,
// the neighbour list is rebuilt every few tens of steps. Reports vertex-steps per second of the step loop.
void run_bench(const Parameters& p, RunContext& ctx)
{
    AssemblySetup setup;
    setup.particles = static_cast<int>(p.integer("particles"));
    setup.ring.nodes = static_cast<int>(p.integer("nodes"));
    setup.seed = static_cast<std::uint64_t>(p.integer("seed"));
    ctx.record_seed(setup.seed);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(setup.particles))));
    Assembly a = rings_in_box(setup, columns);
    const double dt = setup.ring.dt_factor * a.model.critical_time_step();
    a.model.check_time_step(dt);
    const double speed = 0.02 * ring_scales(setup.ring).radius_vertex / dt;
    Rng rng(setup.seed + 1);
    for (int shell : a.particles) {
        const double angle = rng.uniform(0, 2 * std::numbers::pi);
        a.model.set_velocity(shell, speed * Vec2(std::cos(angle), std::sin(angle)));
    }
    const long steps = p.integer("steps");
    a.model.step(dt, 0.0); // first force evaluation and list build outside the timing
    const auto start = std::chrono::steady_clock::now();
    for (long n = 1; n < steps; ++n)
        a.model.step(dt, 0.0);
    const double seconds = seconds_since(start);
    ctx.count_steps(steps);
    const int vertices = particle_vertices(a);
    auto& s = ctx.summary();
    s["vertex_steps_per_second"] = vertices * static_cast<double>(steps - 1) / seconds;
    s["vertices"] = vertices;
    s["threads"] = omp_get_max_threads();
    s["loop_seconds"] = seconds;
    s["contact_candidates_per_vertex"] = static_cast<double>(a.model.contact_candidates()) / vertices;
    s["neighbour_list_builds"] = a.model.neighbour_list_builds();
    s["kinetic_energy_final"] = a.model.kinetic_energy();
    // The assembly's geometry and laws, for an equivalent run in another code (scripts/bench-vs-lammps).
    const RingScales sc = ring_scales(setup.ring);
    s["ring_radius"] = setup.ring.radius;
    s["vertex_radius"] = sc.radius_vertex;
    s["vertex_mass"] = setup.ring.vertex_mass;
    s["k_s"] = sc.laws.k_s;
    s["k_b"] = sc.laws.k_b;
    s["k_n"] = sc.laws.k_s; // contact stiffness of the ring scenes (rings_in_box)
    s["dt"] = dt;
    s["box_width"] = a.width;
    s["box_height"] = a.height;
    s["columns"] = columns;
    s["speed"] = speed;
    s["neighbour_skin"] = a.model.neighbour_skin();
}

} // namespace

void register_spd_assembly_scenes(SceneRegistry& registry)
{
    registry.add(Scene{
        "spd.bench",
        "SPD speed: elastic rings colliding in a box; vertex-steps per second of the time-step loop",
        {
            ParameterSpec::integer("particles", 400, "1", "number of rings").at_least(1),
            ParameterSpec::integer("nodes", 32, "1", "vertices per ring").at_least(8),
            ParameterSpec::integer("steps", 2000, "1", "time steps (the first is not timed)").at_least(2),
            ParameterSpec::integer("seed", 1, "1", "seed of the initial velocities").non_negative(),
        },
        run_bench});
}

} // namespace softgrain
