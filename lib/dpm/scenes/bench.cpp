// dpm.bench: what it costs to jam one packing and to take its spectrum (issue 19), for `make bench`.
//
// dimension = 2: the dpm.jam protocol (jam.hpp) with dpm.jam's parameters. dimension = 3: the 3D protocol
// (jam3d.hpp) with the same parameters mapped onto it: model, particles, seed, relaxation, pressure_onset,
// pressure_max and pressures (in k_v v0), A0 (as A0^3D), fire_step as they are; both particle sizes on one mesh
// whose vertex count nodes_small = nodes_large names it (mesh_for_nodes); rough contacts as in 2D; the rest
// (stiffnesses, FIRE budget, saddle escapes, size ratio 1.4) at the protocol's defaults; kl_surface has no
// 3D counterpart. Reported (summary.json): jam_seconds (the whole protocol, wall time) and jam_cpu_seconds
// (its process CPU time: the cost on a loaded machine), relax_seconds (the relaxations in it) and
// fire_seconds (their FIRE part), fire_iterations, force_evaluations (energy and gradient evaluations of the
// FIRE runs: one per FIRE iteration and one at the start of each), force_evaluations_per_second and
// vertex_force_evaluations_per_second (over fire_seconds: FIRE's rate), newton_handovers, newton_steps and
// newton_factorizations (the Newton finisher of relaxation = fire_newton, newton_relax.hpp, in either
// dimension; 0 with FIRE alone), degrees_of_freedom; the run's peak memory is peak_memory_mib.
// The spectrum (eq. 9.28) of the jammed packing, or of its tiling `replicate` times along each axis
// (replicate_periodic_packing: an equilibrium k^dimension times as large, whose spectrum costs what that of
// a jammed packing of that size would, without the cost of jamming one): spectrum_seconds,
// spectrum_degrees_of_freedom and spectrum_modes, every mode of the dense matrix (lowest_modes = 0) or the
// lowest ones by shift-and-invert Lanczos on the sparse matrix (sparse_modes.hpp), with its
// spectrum_factorizations and spectrum_solves. Costs are measured, never asserted
// (verification/dpm/protocols/bench.cpp checks that the keys agree with each other).
#include "dpm/scenes/scenes.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/system/scale_packing.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>

namespace softgrain::dpm {

namespace {

// dpm.bench's options: the dpm.jam protocol, timed in 2D or mapped onto the 3D protocol.
struct BenchOptions
{
    JamOptions jam;
    int dimension = 2;
    HessianStorage hessian3d = HessianStorage::automatic;
    int lowest_modes = 0; // 0: every mode of the dense matrix
    int replicate = 1;    // the spectrum's packing: the jammed one tiled replicate^dimension times
};

// What a jamming run cost, in either dimension.
struct JamCost
{
    double jam_seconds = 0, jam_cpu_seconds = 0, relax_seconds = 0, fire_seconds = 0;
    long fire_iterations = 0, force_evaluations = 0, newton_handovers = 0, newton_steps = 0,
         newton_factorizations = 0;
    Eigen::Index degrees_of_freedom = 0, vertices = 0;
};

// What the spectrum of a packing cost.
struct SpectrumCost
{
    double seconds = 0;
    Eigen::Index degrees_of_freedom = 0, modes = 0;
    int factorizations = 0, solves = 0; // of the shift-and-invert Lanczos iteration (lowest_modes > 0)
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
    options3d.fire_step = options.fire_step;
    options3d.hessian = hessian;
    return options3d;
}

// Degrees of freedom of the spectrum's packing: dimension x vertices x replicate^dimension.
double spectrum_degrees_of_freedom(const BenchOptions& options)
{
    return options.dimension * bidisperse_vertices(bidisperse_packing(options.jam)) *
           std::pow(options.replicate, options.dimension);
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
    binding
        .integer(&BenchOptions::lowest_modes, "lowest_modes", "1",
                 "0: the spectrum is every mode of the dense dynamical matrix; K > 0: its K lowest modes by "
                 "shift-and-invert Lanczos on the sparse matrix (K below the spectrum's degrees of freedom)")
        .at_least(0);
    binding
        .integer(&BenchOptions::replicate, "replicate", "1",
                 "the spectrum is taken of the jammed packing tiled replicate times along each axis "
                 "(replicate^dimension copies in a box replicate times as large: an equilibrium of that "
                 "size, jammed at the cost of one copy); 1: the jammed packing itself")
        .at_least(1);
    // In 3D the model and the vertex counts must name 3D particles, and the lowest modes must be fewer
    // than the spectrum's degrees of freedom: refused before anything runs.
    binding.check([](const BenchOptions& options) {
        if (options.dimension == 3) jam_options_3d(options.jam, options.hessian3d);
        const double n = spectrum_degrees_of_freedom(options);
        if (options.lowest_modes >= n)
            throw InputError("lowest_modes = " + std::to_string(options.lowest_modes) +
                             " for a spectrum of " + number_text(n) +
                             " degrees of freedom (dimension x vertices x replicate^dimension); allowed: 0 "
                             "(every mode) or fewer than that");
    });
    return binding;
}

// Every mode of the dense dynamical matrix (eq. 9.28), as the scenes take it by default: every eigenvalue
// and eigenvector (Eigen's SelfAdjointEigenSolver). Returns the number of modes.
Eigen::Index dense_spectrum(const DpmSystem& system, const Eigen::VectorXd& x)
{
    return vibrational_modes(system, x).eigenvalues.size();
}

Eigen::Index dense_spectrum(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
    total_energy3d(system, x, nullptr, &m);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues().size();
}

Eigen::SparseMatrix<double> sparse_matrix(const DpmSystem& system, const Eigen::VectorXd& x)
{
    return sparse_dynamical_matrix(system, x);
}

Eigen::SparseMatrix<double> sparse_matrix(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    return sparse_dynamical_matrix3d(system, x);
}

// The spectrum of the jammed packing (system, x), tiled `replicate` times along each axis first, timed:
// every mode (lowest = 0) or the `lowest` ones.
template <int Dim, class System>
SpectrumCost measure_spectrum(System system, Eigen::VectorXd x, int lowest, int replicate)
{
    replicate_periodic_packing<Dim>(system, x, replicate);
    SpectrumCost cost;
    cost.degrees_of_freedom = x.size();
    const auto start = std::chrono::steady_clock::now();
    if (lowest == 0) {
        cost.modes = dense_spectrum(system, x);
    } else {
        const LowestModes found = lowest_modes(sparse_matrix(system, x), lowest);
        cost.modes = found.spectrum.eigenvalues.size();
        cost.factorizations = found.factorizations;
        cost.solves = found.solves;
    }
    cost.seconds = seconds_since(start);
    return cost;
}

// Runs `jam_packing` and times it (2D: to the last target pressure; 3D: to P_t); returns its cost and the
// jammed packing.
template <class Jam>
auto measure_jam(const Jam& jam_packing)
{
    JamCost cost;
    const auto start = std::chrono::steady_clock::now();
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
    return std::pair{cost, result};
}

void run_bench(const BenchOptions& options, RunContext& context)
{
    const JamOptions& jam_options = options.jam;
    const int dimension = options.dimension;
    context.record_seed(jam_options.seed);
    JamCost cost;
    SpectrumCost spectrum;
    if (dimension == 2) {
        const auto [jammed, packing] = measure_jam([&jam_options] { return jam(jam_options); });
        cost = jammed;
        spectrum = measure_spectrum<2>(packing.system, packing.x, options.lowest_modes, options.replicate);
    } else {
        const Jam3dOptions jam3d_options = jam_options_3d(jam_options, options.hessian3d);
        const auto [jammed, packing] = measure_jam([&jam3d_options] { return jam3d(jam3d_options); });
        cost = jammed;
        spectrum = measure_spectrum<3>(packing.system, packing.x, options.lowest_modes, options.replicate);
    }
    cost.vertices = cost.degrees_of_freedom / dimension;
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
    summary["spectrum_seconds"] = spectrum.seconds;
    summary["spectrum_degrees_of_freedom"] = spectrum.degrees_of_freedom;
    summary["spectrum_modes"] = spectrum.modes;
    summary["spectrum_factorizations"] = spectrum.factorizations;
    summary["spectrum_solves"] = spectrum.solves;
}

// The spectrum of n = dimension x vertices x replicate^dimension degrees of freedom. Every mode: two dense
// n x n matrices. The K lowest: the sparse matrix, whose shape terms (eqs. 9.1, 9.2: the area or volume
// penalty) couple every pair of a particle's coordinates, (dimension N_mu)^2 non-zeros per particle, each
// an assembly triplet (16 B), in M (12 B) and in the lower half of its LDL^T factor (6 B), as
// packing3d_memory counts them; and the Lanczos basis of max(2 K + 1, K + 40) vectors of n doubles. In 3D,
// at least the protocol's own Hessian (packing3d_memory).
MemoryEstimate spectrum_memory(const BenchOptions& options)
{
    const BidispersePacking packing = bidisperse_packing(options.jam);
    const double n = spectrum_degrees_of_freedom(options);
    const std::string what = packing.disks ? "dimension x particles x replicate^dimension"
                                           : "dimension x particles x (nodes_small + nodes_large) / 2 x "
                                             "replicate^dimension";
    if (options.lowest_modes == 0) return dense_matrix_memory(n, 2, what);
    const double copies = packing.particles * std::pow(options.replicate, options.dimension);
    const double per_particle = n / copies;
    const int basis = std::max(2 * options.lowest_modes + 1, options.lowest_modes + 40);
    return {copies * per_particle * per_particle * 34.0 + basis * n * sizeof(double),
            "the sparse dynamical matrix, (dimension N_mu)^2 non-zeros of 34 B per particle, and " +
                std::to_string(basis) + " Lanczos vectors of n doubles, n = " + what + " = " +
                number_text(n)};
}

MemoryEstimate bench_memory(const BenchOptions& options)
{
    const MemoryEstimate spectrum = spectrum_memory(options);
    if (options.dimension == 2) return spectrum;
    const Jam3dOptions protocol = jam_options_3d(options.jam, options.hessian3d);
    const MemoryEstimate jamming = packing3d_memory(protocol.particles, protocol.mesh, protocol.hessian, 0);
    return jamming.bytes > spectrum.bytes ? jamming : spectrum;
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
