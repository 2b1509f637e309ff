// dpm.bench: what it costs to jam one packing and to take its spectrum (issue 19), for `make bench`.
//
// dimension = 2: the dpm.jam protocol (jam.hpp) with dpm.jam's parameters. dimension = 3: the 3D protocol
// (jam3d.hpp) with the same parameters mapped onto it: model, particles, seed, relaxation, pressure_onset,
// pressure_max and pressures (in k_v v0), A0 (as A0^3D) as they are; both particle sizes on one mesh
// whose vertex count nodes_small = nodes_large names it (mesh_for_nodes); rough contacts as in 2D; the rest
// (stiffnesses, FIRE budget, saddle escapes, size ratio 1.4) at the protocol's defaults; kl_surface has no
// 3D counterpart. Reported (summary.json): jam_seconds (the whole protocol, wall time) and jam_cpu_seconds
// (its process CPU time: the cost on a loaded machine), relax_seconds (the relaxations in it) and
// fire_seconds (their FIRE part), fire_iterations, force_evaluations (energy and gradient evaluations of the
// FIRE runs: one per FIRE iteration and one at the start of each), force_evaluations_per_second and
// vertex_force_evaluations_per_second (over fire_seconds: FIRE's rate), newton_handovers, newton_steps and
// newton_factorizations (the Newton finisher of relaxation = fire_newton, newton_relax.hpp, in either
// dimension; 0 with FIRE alone), spectrum_seconds, degrees_of_freedom; the run's peak memory is
// peak_memory_mib. Costs are measured, never asserted (verification/dpm/protocols/bench.cpp checks that the keys agree with each other).
#include "dpm/scenes/scenes.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <chrono>
#include <ctime>

namespace softgrain::dpm {

namespace {

// dpm.bench's options: the dpm.jam protocol, timed in 2D or mapped onto the 3D protocol.
struct BenchOptions
{
    JamOptions jam;
    int dimension = 2;
    HessianStorage hessian3d = HessianStorage::automatic;
};

// What a jamming run cost, in either dimension.
struct JamCost
{
    double jam_seconds = 0, jam_cpu_seconds = 0, relax_seconds = 0, fire_seconds = 0, spectrum_seconds = 0;
    long fire_iterations = 0, force_evaluations = 0, newton_handovers = 0, newton_steps = 0,
         newton_factorizations = 0;
    Eigen::Index degrees_of_freedom = 0, vertices = 0, modes = 0;
};

// The meshes of the 3D protocol by vertex count.
const std::array<const char*, 6> meshes3d{"tetrahedron", "octahedron",  "icosahedron",
                                          "geodesic42",  "geodesic162", "geodesic642"};

std::string mesh_for_nodes(const JamOptions& options)
{
    std::string allowed;
    for (const char* name : meshes3d) {
        const int count = mesh_from_name(name).vertex_count();
        if (options.nodes_small == count && options.nodes_large == count) return name;
        allowed += (allowed.empty() ? "" : ", ") + std::to_string(count) + " (" + name + ")";
    }
    throw InputError("nodes_small = " + std::to_string(options.nodes_small) +
                     " and nodes_large = " + std::to_string(options.nodes_large) +
                     " with dimension = 3: both particle sizes use one mesh; allowed equal vertex counts " +
                     allowed);
}

// The 3D protocol's options for dpm.jam's (see the header comment).
Jam3dOptions jam_options_3d(const JamOptions& options, HessianStorage hessian)
{
    const std::optional<ShapeModel> model = shape_model(options.model);
    if (!model)
        throw InputError("model = '" + jam_model_name(options.model) +
                         "' with dimension = 3: allowed shell | floppy | surface_tension");
    Jam3dOptions options3d;
    options3d.model = *model;
    options3d.particles = options.particles;
    options3d.mesh = mesh_for_nodes(options);
    options3d.size_ratio = options.size_ratio;
    options3d.pressure_onset = options.pressure_onset;
    options3d.pressure_max = options.pressure_max;
    options3d.pressures = options.pressures;
    options3d.A0_floppy = options.A0_floppy;
    options3d.seed = options.seed;
    options3d.interaction = InteractionKind::rough;
    options3d.relaxation = options.relaxation;
    options3d.hessian = hessian;
    return options3d;
}

OptionBinding<BenchOptions> bench_binding()
{
    OptionBinding<BenchOptions> binding;
    bind_jam_protocol(binding, &BenchOptions::jam);
    binding
        .integer(
            &BenchOptions::dimension, "dimension", "1",
            "2: the dpm.jam protocol; 3: the 3D protocol of dpm.modes3d (jam3d.hpp), nodes_small = "
            "nodes_large = its mesh's vertices (4, 6, 12, 42, 162, 642), pressures in k_v v0, kl_surface "
            "unused")
        .at_least(2)
        .at_most(3);
    bind_hessian_storage(binding, &BenchOptions::hessian3d, "hessian3d",
                         "dimension = 3: the protocol's FIRE time step and saddle tests");
    // In 3D the model and the vertex counts must name 3D particles: refused before anything runs.
    binding.check([](const BenchOptions& options) {
        if (options.dimension == 3) jam_options_3d(options.jam, options.hessian3d);
    });
    return binding;
}

// The spectrum of the jammed packing (eq. 9.28) as the scenes take it today: every eigenvalue and
// eigenvector of the dense dynamical matrix (Eigen's SelfAdjointEigenSolver). Returns the number of modes.
Eigen::Index packing_spectrum(const DpmSystem& system, const Eigen::VectorXd& x)
{
    return vibrational_modes(system, x).eigenvalues.size();
}

Eigen::Index packing_spectrum(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
    total_energy3d(system, x, nullptr, &m);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues().size();
}

// Runs `jam_packing` and the spectrum of the packing it returns (2D: at the last target pressure; 3D: at
// P_t), timing both.
template <class Jam>
JamCost measure(const Jam& jam_packing)
{
    JamCost cost;
    auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const auto result = jam_packing();
    cost.jam_cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    cost.jam_seconds = seconds_since(start);
    cost.relax_seconds = result.relax_seconds;
    cost.fire_seconds = result.fire_seconds;
    cost.newton_handovers = result.handovers;
    cost.newton_steps = result.newton_steps;
    cost.newton_factorizations = result.factorizations;
    cost.fire_iterations = result.fire_iterations;
    cost.force_evaluations = result.force_evaluations;
    cost.degrees_of_freedom = result.x.size();
    start = std::chrono::steady_clock::now();
    cost.modes = packing_spectrum(result.system, result.x);
    cost.spectrum_seconds = seconds_since(start);
    return cost;
}

void run_bench(const BenchOptions& options, RunContext& context)
{
    const JamOptions& jam_options = options.jam;
    const int dimension = options.dimension;
    context.record_seed(jam_options.seed);
    JamCost cost;
    if (dimension == 2) {
        cost = measure([&jam_options] { return jam(jam_options); });
        cost.vertices = cost.degrees_of_freedom / 2;
    } else {
        const Jam3dOptions jam3d_options = jam_options_3d(jam_options, options.hessian3d);
        cost = measure([&jam3d_options] { return jam3d(jam3d_options); });
        cost.vertices = cost.degrees_of_freedom / 3;
    }
    context.count_steps(cost.fire_iterations);
    auto& summary = context.summary();
    summary["dimension"] = dimension;
    summary["degrees_of_freedom"] = cost.degrees_of_freedom;
    summary["vertices"] = cost.vertices;
    summary["jam_seconds"] = cost.jam_seconds;
    summary["jam_cpu_seconds"] = cost.jam_cpu_seconds;
    summary["relax_seconds"] = cost.relax_seconds;
    summary["fire_seconds"] = cost.fire_seconds;
    summary["fire_iterations"] = cost.fire_iterations;
    summary["force_evaluations"] = cost.force_evaluations;
    summary["force_evaluations_per_second"] = static_cast<double>(cost.force_evaluations) / cost.fire_seconds;
    summary["vertex_force_evaluations_per_second"] =
        static_cast<double>(cost.vertices) * static_cast<double>(cost.force_evaluations) / cost.fire_seconds;
    summary["newton_handovers"] = cost.newton_handovers;
    summary["newton_steps"] = cost.newton_steps;
    summary["newton_factorizations"] = cost.newton_factorizations;
    summary["spectrum_seconds"] = cost.spectrum_seconds;
    summary["spectrum_modes"] = cost.modes;
}

// The dense spectrum of the jammed packing: two n x n matrices, n = dimension x vertices.
MemoryEstimate bench_memory(const BenchOptions& options)
{
    const BidispersePacking packing = bidisperse_packing(options.jam);
    return dense_matrix_memory(options.dimension * bidisperse_vertices(packing), 2,
                               packing.disks ? "dimension x particles"
                                             : "dimension x particles x (nodes_small + nodes_large) / 2");
}

} // namespace

Scene bench_scene()
{
    return bound_scene("dpm.bench",
                       "Issue 19: the cost of jamming one packing with the dpm.jam protocol (2D) or the 3D "
                       "protocol, and of its dense spectrum: time, FIRE iterations, force evaluations per "
                       "second (make bench)",
                       bench_binding(), run_bench)
        .needing(bench_binding().estimate(bench_memory))
        .without_vtk("a timed scene: writing frames would change the time it measures; "
                     "dpm.jam and dpm.modes3d draw the packings it times");
}

} // namespace softgrain::dpm
