// spd.bench: the cost of the SPD time-step loop, elastic rings colliding in a box.
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "core/rng.hpp"
#include "spd/assembly.hpp"
#include "spd/scenes/parameters.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/time_step_limits.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <numbers>

namespace softgrain::spd {

namespace {

// spd.bench: `particles` elastic rings (eta = 0) of `nodes` vertices, touching on a square lattice in a box,
// each launched with a random rigid velocity of 0.02 r per time step (r the vertex radius), `steps`
// undamped-in-the-bulk velocity-Verlet steps (contact damping only): rings collide, bend and rearrange,
// the neighbour list is rebuilt every few tens of steps. Reports vertex-steps per second of the step loop.
//
// spd.bench's options: the assembly and the number of time steps.
struct BenchOptions
{
    AssemblySetup setup;
    long steps = 2000;
};

// The scene's defaults where they differ from the library's.
BenchOptions bench_defaults()
{
    BenchOptions options;
    options.setup.particles = 400;
    options.setup.ring.nodes = 32;
    options.setup.ring.dt_factor = 0.2;
    return options;
}

OptionBinding<BenchOptions> bench_binding()
{
    OptionBinding<BenchOptions> binding(bench_defaults());
    binding
        .integer(path(&BenchOptions::setup, &AssemblySetup::particles), "particles", "1", "number of rings")
        .at_least(1);
    binding
        .integer(path(&BenchOptions::setup, &AssemblySetup::ring, &RingSetup::nodes), "nodes", "1",
                 "vertices per ring")
        .at_least(8);
    binding.count(&BenchOptions::steps, "steps", "1", "time steps (the first is not timed)").at_least(2);
    binding.seed(path(&BenchOptions::setup, &AssemblySetup::seed), "seed", "seed of the initial velocities");
    binding
        .real(path(&BenchOptions::setup, &AssemblySetup::ring, &RingSetup::dt_factor), "dt_factor", "1",
              "time step over dt_c = sqrt(m/k_max); below the vertex-pair limit 0.236 "
              "(decision spd-vertex-pair-stability)")
        .positive();
    return binding;
}

// The timed run: the assembly after the last step, its box lattice, the time step, the launch speed and the
// wall time of the step loop.
struct BenchRun
{
    Assembly assembly;
    int columns = 0;
    double dt = 0, speed = 0, seconds = 0;
};

BenchRun time_step_loop(const BenchOptions& options)
{
    const AssemblySetup& setup = options.setup;
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(setup.particles))));
    BenchRun run{rings_in_box(setup, columns), columns};
    ShellModel& model = run.assembly.model;
    run.dt = setup.ring.dt_factor * critical_time_step(model);
    check_time_step(model, run.dt);
    run.speed = 0.02 * ring_scales(setup.ring).radius_vertex / run.dt;
    // A dt_factor so small that the launch speed 0.02 r/dt overflows (4.9e-324 aborted the run).
    if (!std::isfinite(run.speed))
        throw InputError(
            "'dt_factor' = " + number_text(setup.ring.dt_factor) + " gives dt = " + number_text(run.dt) +
            " s and a launch speed 0.02 r/dt that is not finite; allowed: dt_factor with a finite "
            "launch speed");
    Rng rng(setup.seed + 1);
    for (int shell : run.assembly.particles) {
        const double angle = rng.uniform(0, 2 * std::numbers::pi);
        model.set_velocity(shell, run.speed * Vec2(std::cos(angle), std::sin(angle)));
    }
    model.step(run.dt, 0.0); // first force evaluation and list build outside the timing
    const auto start = std::chrono::steady_clock::now();
    for (long n = 1; n < options.steps; ++n)
        model.step(run.dt, 0.0);
    run.seconds = seconds_since(start);
    return run;
}

void report_bench(const BenchOptions& options, const BenchRun& run, RunContext& context)
{
    const AssemblySetup& setup = options.setup;
    const ShellModel& model = run.assembly.model;
    const int vertices = particle_vertices(run.assembly);
    auto& summary = context.summary();
    summary["vertex_steps_per_second"] = vertices * static_cast<double>(options.steps - 1) / run.seconds;
    summary["vertices"] = vertices;
    summary["threads"] = omp_get_max_threads();
    summary["loop_seconds"] = run.seconds;
    summary["contact_candidates_per_vertex"] = static_cast<double>(model.contact_candidates()) / vertices;
    summary["neighbour_list_builds"] = model.neighbour_list_builds();
    summary["kinetic_energy_final"] = model.kinetic_energy();
    // The assembly's geometry and laws, for an equivalent run in another code (scripts/bench-vs-lammps).
    const RingScales scales = ring_scales(setup.ring);
    summary["ring_radius"] = setup.ring.radius;
    summary["vertex_radius"] = scales.radius_vertex;
    summary["vertex_mass"] = setup.ring.vertex_mass;
    summary["k_s"] = scales.laws.k_s;
    summary["k_b"] = scales.laws.k_b;
    summary["k_n"] = scales.laws.k_s; // contact stiffness of the ring scenes (rings_in_box)
    summary["dt"] = run.dt;
    summary["box_width"] = run.assembly.width;
    summary["box_height"] = run.assembly.height;
    summary["columns"] = run.columns;
    summary["speed"] = run.speed;
    summary["neighbour_skin"] = model.neighbour_skin();
}

void run_bench(const BenchOptions& options, RunContext& context)
{
    context.record_seed(options.setup.seed);
    const BenchRun run = time_step_loop(options);
    context.count_steps(options.steps);
    report_bench(options, run, context);
}

} // namespace

Scene bench_scene()
{
    return bound_scene(
               "spd.bench",
               "SPD speed: elastic rings colliding in a box; vertex-steps per second of the time-step loop",
               bench_binding(), run_bench)
        .needing(
            bench_binding().estimate([](const BenchOptions& options) { return rings_memory(options.setup); }))
        .without_vtk("a timed scene: writing frames would change the time it measures; "
                     "spd.compaction draws colliding rings");
}

} // namespace softgrain::spd
