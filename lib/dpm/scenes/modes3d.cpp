// dpm.modes3d: eigenvalues of the dynamical matrix (eq. 9.28) of a single floppy, shell or surface-tension
// particle in 3D (Fig. 9.15a), or (particles > 1) of a jammed bidisperse packing of them at pressure P_t
// (jam3d.hpp, Fig. 9.15b).
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/mode_energy.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/packing_hessian3d.hpp"
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/protocols/single_particle3d.hpp"
#include "dpm/scenes/scenes.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace softgrain::dpm {

namespace {

// dpm.modes3d's options: the particle (a single one, or the jamming protocol of a packing of them) and the
// spectrum.
struct Modes3dOptions
{
    Jam3dOptions jam = scene_jam_defaults();
    std::optional<double> A0 = 1.04; // nothing: `min`, the mesh's own A^3D
    double soft_threshold = 1e-4;    // [k_v v0^(4/3)]
    int lowest_modes = 0;            // 0: every mode (dense)

    // The scene's defaults where they differ from the library's.
    static Jam3dOptions scene_jam_defaults()
    {
        Jam3dOptions jam;
        jam.model = ShapeModel::floppy;
        jam.particles = 1;
        return jam;
    }
};

OptionBinding<Modes3dOptions> modes3d_binding()
{
    const auto jam = [](auto... field) { return path(&Modes3dOptions::jam, field...); };
    OptionBinding<Modes3dOptions> binding;
    binding.choice(jam(&Jam3dOptions::model), "model",
                   {{"floppy", ShapeModel::floppy},
                    {"shell", ShapeModel::shell},
                    {"surface_tension", ShapeModel::surface_tension}},
                   "particle type of Table 9.1 (3D analogues)");
    binding.word(jam(&Jam3dOptions::mesh), "mesh", particle_mesh_names(), "surface mesh of the particle");
    binding
        .real_or_keyword(&Modes3dOptions::A0, "A0", "min", "1",
                         "preferred shape parameter (sum a_f0)^(3/2)/(6 sqrt(pi) v0); min selects the "
                         "mesh's own A^3D (A_min of the text)")
        .at_least(1.0);
    binding
        .real(jam(&Jam3dOptions::stiffness, &Stiffness3d::ka), "ka", "k_v v0^(2/3)",
              "face-area stiffness k_a")
        .positive();
    binding
        .real(jam(&Jam3dOptions::stiffness, &Stiffness3d::kb), "kb", "k_v v0^2",
              "bending stiffness k_b (shell)")
        .positive();
    binding
        .real(jam(&Jam3dOptions::stiffness, &Stiffness3d::gamma), "gamma", "k_v v0^(5/3)",
              "surface tension gamma (surface_tension)")
        .positive();
    binding
        .real(jam(&Jam3dOptions::zero_threshold), "zero_threshold", "k_v v0^(4/3)",
              "zero mode: lambda~ below this (Fig. 9.15a), or below the round-off bound n eps "
              "max|lambda~| where that is larger (summary zero_threshold_used)")
        .positive();
    binding.seed(jam(&Jam3dOptions::seed), "seed",
                 "seed of the random displacement of the start (single particle) or of the random "
                 "positions and orientations (packing)");
    binding
        .integer(jam(&Jam3dOptions::particles), "particles", "1",
                 "1: a single particle (Fig. 9.15a); an even number >= 2: a jammed 50:50 bidisperse "
                 "packing of that many particles in a periodic cube (Fig. 9.15b)")
        .at_least(1);
    binding
        .real(jam(&Jam3dOptions::pressure_onset), "pressure", "k_v v0",
              "packing: jamming pressure P_t (1 <= P/P_t < 1.01)")
        .positive();
    binding
        .real(jam(&Jam3dOptions::size_ratio), "size_ratio", "1",
              "packing: diameter ratio of large to small particles")
        .at_least(1.0);
    binding.choice(jam(&Jam3dOptions::interaction), "contact",
                   {{"rough", InteractionKind::rough}, {"smooth", InteractionKind::smooth}},
                   "packing: contacts between particles: rough = vertex spheres of diameter sigma "
                   "(eqs. 9.3-9.4), smooth = each vertex sphere against the faces of the other "
                   "particle's mesh (sphero-polyhedra, Fig. 9.6d; decision "
                   "dpm-3d-smooth-inclusion-exclusion)");
    binding
        .real(&Modes3dOptions::soft_threshold, "soft_threshold", "k_v v0^(4/3)",
              "packing: a non-zero mode below this counts as soft (low-frequency), summary soft_modes")
        .positive();
    binding
        .integer(jam(&Jam3dOptions::saddle_escapes), "saddle_escapes", "1",
                 "packing: at most this many moves off a saddle at P_t, each followed by "
                 "compression to P_t again (decision dpm-packing-minimum); 0: the protocol's "
                 "first state is kept. Summary saddle_escapes: the moves made")
        .non_negative();
    bind_relaxation(binding, jam(&Jam3dOptions::relaxation), "packing: the 3D jamming protocol");
    bind_fire_step(binding, jam(&Jam3dOptions::fire_step));
    bind_hessian_storage(binding, jam(&Jam3dOptions::hessian), "hessian",
                         "packing: the jamming protocol's FIRE time step and saddle tests (the spectrum "
                         "follows lowest_modes)");
    // A count of FIRE steps (a long in the protocol) with the range it always had.
    binding
        .count(jam(&Jam3dOptions::fire_budget), "fire_budget", "1",
               "packing: FIRE steps allowed per relaxation of the jamming protocol; a "
               "relaxation that needs more stops the run with exit 3 (decision "
               "dpm-3d-jam-paper-size)")
        .at_least(1)
        .at_most(std::numeric_limits<int>::max());
    binding
        .real(jam(&Jam3dOptions::jump_step), "jump_step", "1",
              "packing: compressing towards P_t, an overshoot of the window at a box step "
              "Delta L/L below this is kept and P_t approached from above by decompression (a "
              "rearrangement that makes P jump over the window); 0: every overshoot is undone "
              "and the step halved (decision dpm-3d-jam-paper-size)")
        .non_negative();
    binding
        .integer(
            &Modes3dOptions::lowest_modes, "lowest_modes", "1",
            "packing: 0 = every mode by the dense eigensolver; K > 0 = only the K lowest, by "
            "shift-and-invert "
            "Lanczos on the sparse dynamical matrix (large packings). With K: lambda_max from Lanczos, no "
            "lambda_median_nonzero, quartic_modes or soft_modes (they need every mode), and K must reach a "
            "non-zero mode (summary modes_computed)")
        .non_negative();
    binding.check([](const Modes3dOptions& options) {
        const bool packing = options.jam.particles > 1;
        if (!packing && options.lowest_modes != 0)
            throw InputError(
                "lowest_modes = " + std::to_string(options.lowest_modes) +
                " with particles = 1; allowed: 0 (a single particle's spectrum is dense and small)");
        if (packing && options.jam.model == ShapeModel::floppy && !options.A0)
            throw InputError(
                "parameter 'A0' = 'min' for floppy packings; allowed: a real number above the mesh's "
                "own A^3D (floppy particles need A0 > A_min)");
    });
    return binding;
}

// The zero-mode threshold of a spectrum `lambda` of n = degrees_of_freedom (every mode, or the lowest ones
// with the separately computed `largest`): zero_threshold, or the round-off bound where that is larger
// (zero_mode_threshold).
double spectrum_threshold(const Eigen::VectorXd& lambda, Eigen::Index degrees_of_freedom, double largest,
                          double zero_threshold)
{
    return zero_mode_threshold(degrees_of_freedom, std::max(std::abs(lambda(0)), largest), zero_threshold);
}

// Writes the spectrum (ascending, already in k_v v0^(4/3)) and returns its counts: zero modes below
// zero_threshold in magnitude, or below the round-off bound where that is larger (zero_mode_threshold).
// `lambda` holds every mode of the n = degrees_of_freedom, or only the lowest ones (lowest_modes): then
// lambda_max is the separately computed `largest`, the median non-zero eigenvalue is not written, and the
// modes must reach a non-zero one (else the zero-mode count is incomplete: InputError).
SpectrumCounts write_spectrum(const Eigen::VectorXd& lambda, Eigen::Index degrees_of_freedom, double largest,
                              double zero_threshold, RunContext& context)
{
    const bool every_mode = lambda.size() == degrees_of_freedom;
    auto& spectrum =
        context.table("eigenvalues.dat", {{"k", "1", "mode index, ascending eigenvalue"},
                                          {"lambda", "k_v v0^(4/3)", "eigenvalue lambda~_k of M, eq. (9.28)"},
                                          {"abs_lambda", "k_v v0^(4/3)", "|lambda~_k| (for log axes)"}});
    for (Eigen::Index i = 0; i < lambda.size(); ++i)
        spectrum.row({double(i + 1), lambda(i), std::abs(lambda(i))});
    const double threshold = spectrum_threshold(lambda, degrees_of_freedom, largest, zero_threshold);
    const SpectrumCounts counts = count_modes(lambda, threshold);
    const int positive = counts.first_positive();
    if (!every_mode && positive >= lambda.size())
        throw InputError("lowest_modes = " + std::to_string(lambda.size()) +
                         ": all of them are zero or negative modes (threshold " + std::to_string(threshold) +
                         "), so the zero-mode count is incomplete; allowed: a larger lowest_modes");
    auto& summary = context.summary();
    summary["zero_modes"] = counts.zero;
    summary["negative_modes"] = counts.negative;
    summary["zero_threshold_used"] = threshold;
    summary["lambda_lowest"] = lambda(0);
    summary["lambda_largest_zero"] =
        counts.zero > 0 ? nlohmann::json(lambda(positive - 1)) : nlohmann::json(nullptr);
    summary["lambda_smallest_nonzero"] =
        positive < lambda.size() ? nlohmann::json(lambda(positive)) : nlohmann::json(nullptr);
    summary["lambda_max"] = every_mode ? lambda(lambda.size() - 1) : largest;
    summary["modes_computed"] = lambda.size();
    if (!every_mode) return counts;
    // The median non-zero eigenvalue: a quadratic (shape or contact) mode whenever the soft band holds
    // fewer than half of the modes (Fig. 9.15d-f).
    summary["lambda_median_nonzero"] = positive < lambda.size()
                                           ? nlohmann::json(lambda(positive + (lambda.size() - positive) / 2))
                                           : nlohmann::json(nullptr);
    return counts;
}

// Fig. 9.15(c): Delta U = U(x + dr e_k) - U(x) along every unit eigenvector e_k of the packing at
// dr = 10^(-3 + s/8) v0^(1/3), s = 0 ... 28 (1e-3 to 3.2), in the table mode_energy.dat, with the quartic
// flag of each mode; summary: the median local exponent d ln dU/d ln dr at dr = 1e-3 over the non-zero modes
// (quadratic: 2) and between dr = 0.1 and 0.2 over the soft modes (quartic at large dr: 4), as measured by
// mode_energies (packing_modes3d).
void write_mode_energy3d(const Eigen::VectorXd& lambda, const ModeEnergies& energies, int first_positive,
                         int soft_end, RunContext& context)
{
    auto& table = context.table(
        "mode_energy.dat", {{"k", "1", "mode index"},
                            {"lambda", "k_v v0^(4/3)", "eigenvalue lambda~_k"},
                            {"zero_mode", "1", "1 if lambda~_k < zero_threshold_used"},
                            {"quartic", "1", "1 if Delta U(0.1 sigma) > 3 lambda dr^2/2 (quartic_modes)"},
                            {"dr", "v0^(1/3)", "amplitude Delta r along the unit eigenvector"},
                            {"dU", "k_v v0^2", "Delta U = U(x + dr e_k) - U(x)"}});
    for (Eigen::Index k = 0; k < lambda.size(); ++k) {
        const ModeEnergy& mode = energies.modes[static_cast<std::size_t>(k)];
        for (std::size_t s = 0; s < energies.amplitudes.size(); ++s)
            table.row({double(k + 1), lambda(k), k < first_positive ? 1.0 : 0.0, mode.quartic ? 1.0 : 0.0,
                       energies.amplitudes[s], mode.delta_u[s]});
    }
    auto& summary = context.summary();
    summary["quadratic_mode_exponent"] = value_or_null(
        median_exponent(energies.modes, first_positive, energies.modes.size(), &ModeEnergy::exponent_small));
    summary["soft_mode_exponent_large"] =
        value_or_null(median_exponent(energies.modes, first_positive, soft_end, &ModeEnergy::exponent_large));
}

// e.M_shape.e: the curvature of the particles' shape energies (eq. 9.2) along the unit mode e, from their
// Hessian M_shape, dense or (above dense_hessian_limit3d) sparse, as the protocol's.
double shape_curvature_along(const DpmSystem3d& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode)
{
    std::vector<Eigen::Triplet<double>> triplets;
    const bool sparse = uses_sparse_hessian(HessianStorage::automatic, x.size());
    Eigen::MatrixXd dense = sparse ? Eigen::MatrixXd() : Eigen::MatrixXd::Zero(x.size(), x.size());
    for (const Particle3d& particle : system.particles)
        shape_energy3d(particle.shape, system.meshes[particle.mesh], x, particle.first, nullptr,
                       sparse ? HessianSink(&triplets) : HessianSink(&dense));
    if (!sparse) return mode.dot(dense * mode);
    Eigen::SparseMatrix<double> shape_hessian(x.size(), x.size());
    shape_hessian.setFromTriplets(triplets.begin(), triplets.end());
    return mode.dot(shape_hessian * mode);
}

// The softest non-zero mode e of a packing (Fig. 9.15d-f, decision dpm-3d-surface-tension-slope): its shares
// of |e|^2 in rigid particle translations, rotations and deformations (decompose_mode), and the fraction
// e.M_shape.e / lambda of its eigenvalue that comes from the shape energies (eq. 9.2) of the particles; the
// rest, 1 minus it, is the contacts' (their stretching, positive, and their pre-stress, -f/r per contact
// across its normal, negative). The softest non-zero mode is column `first_positive` of `modes`
// (eigenvalues ascending in the units of M, SpectrumCounts); the keys are null if there is none.
void write_softest_mode3d(const DpmSystem3d& system, const Eigen::VectorXd& x,
                          const Eigen::VectorXd& eigenvalues, const Eigen::MatrixXd& modes,
                          int first_positive, RunContext& context)
{
    auto& summary = context.summary();
    const char* keys[] = {"softest_mode_translation", "softest_mode_rotation", "softest_mode_deformation",
                          "softest_mode_shape_energy_fraction"};
    if (first_positive >= eigenvalues.size()) {
        for (const char* key : keys)
            summary[key] = nullptr;
        return;
    }
    const Eigen::VectorXd mode = modes.col(first_positive);
    const ModeParts parts = decompose_mode(system, x, mode);
    summary[keys[0]] = parts.translation;
    summary[keys[1]] = parts.rotation;
    summary[keys[2]] = parts.deformation;
    summary[keys[3]] = shape_curvature_along(system, x, mode) / eigenvalues(first_positive);
}

// Where the zero modes beyond the 3 uniform translations live (nontrivial_zero_mode_parts), particle by
// particle, with its vertex contacts: table zero_modes.dat; summary nontrivial_zero_modes, the dimension of
// that subspace.
void write_zero_mode_parts3d(const DpmSystem3d& system, const Eigen::VectorXd& x,
                             const Eigen::MatrixXd& zero_modes, const std::vector<int>& contacts,
                             RunContext& context)
{
    int dimension = 0;
    const std::vector<ModeParts> parts = nontrivial_zero_mode_parts(system, x, zero_modes, dimension);
    auto& table =
        context.table("zero_modes.dat",
                      {{"particle", "1", "particle index (the first half small)"},
                       {"contacts", "1", "vertex contacts of the particle"},
                       {"translation", "1", "share of the non-trivial zero modes in its rigid translation"},
                       {"rotation", "1", "share in its rigid rotation"},
                       {"deformation", "1", "share in its deformation"}});
    for (std::size_t m = 0; m < parts.size(); ++m)
        table.row(
            {double(m), double(contacts[m]), parts[m].translation, parts[m].rotation, parts[m].deformation});
    context.summary()["nontrivial_zero_modes"] = dimension;
}

// The packing's modes: every one by the dense eigensolver (lowest = 0), or the `lowest` lowest by
// shift-and-invert Lanczos on the sparse matrix (sparse_modes.hpp); `largest` is max lambda [k_c].
struct ComputedModes3d
{
    ModeSpectrum modes;
    double largest = 0;
};
ComputedModes3d compute_modes3d(const DpmSystem3d& system, const Eigen::VectorXd& x, int lowest)
{
    if (lowest == 0) {
        Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
        total_energy3d(system, x, nullptr, &m);
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(m);
        return {{solver.eigenvalues(), solver.eigenvectors()}, solver.eigenvalues()(x.size() - 1)};
    }
    if (lowest >= x.size())
        throw InputError("lowest_modes = " + std::to_string(lowest) + " for " + std::to_string(x.size()) +
                         " degrees of freedom; allowed: 0 (every mode, dense) or 1 ... " +
                         std::to_string(x.size() - 1));
    LowestModes found = lowest_modes(sparse_dynamical_matrix3d(system, x), lowest);
    return {std::move(found.spectrum), found.largest_eigenvalue};
}

// Fig. 9.15(b): a jammed packing at P_t, Newton-polished to round-off forces first (a residual force f shifts
// the zero modes by ~f R), and its modes. The protocol moves a packing off a saddle and compresses it again
// (jam3d.hpp); one left after `saddle_escapes` moves shows as negative modes (decision dpm-packing-minimum).
// Delta U along each mode (Fig. 9.15c; mode_energies): soft modes are those below soft_threshold, quartic
// ones (decision dpm-quartic-criterion as in 2D) have Delta U at Delta r = 0.1 sigma above 3 times the
// harmonic lambda Delta r^2/2.
struct PackingModes3d
{
    Jam3dResult packing;
    double force_max = 0; // after the polish [k_c sigma]
    ComputedModes3d computed;
    double spectrum_seconds = 0;
    Eigen::VectorXd lambda; // [k_v v0^(4/3)]
    SpectrumCounts counts;  // of lambda
    int soft_end = 0;       // the modes below soft_threshold, a prefix of the ascending spectrum
    ModeEnergies energies;  // lengths v0^(1/3), energies k_v v0^2
};

PackingModes3d packing_modes3d(const Modes3dOptions& options)
{
    Jam3dOptions jam = options.jam;
    if (jam.model == ShapeModel::floppy) jam.A0_floppy = *options.A0;
    PackingModes3d result;
    result.packing = jam3d(jam);
    const Jam3dResult& packing = result.packing;
    result.force_max = polish_for_modes3d(packing.system, result.packing.x, packing.pressure_unit,
                                          HessianStorage::automatic);
    const auto started = std::chrono::steady_clock::now();
    result.computed = compute_modes3d(packing.system, packing.x, options.lowest_modes);
    result.spectrum_seconds = seconds_since(started);
    result.lambda = result.computed.modes.eigenvalues / packing.eigenvalue_unit;
    result.counts =
        count_modes(result.lambda, spectrum_threshold(result.lambda, packing.x.size(),
                                                      result.computed.largest / packing.eigenvalue_unit,
                                                      options.jam.zero_threshold));
    result.soft_end = static_cast<int>((result.lambda.array() < options.soft_threshold).count());
    ModeEnergyOptions along;
    along.amplitudes = 29;
    along.length_unit = packing.length_unit;
    along.energy_unit = packing.energy_unit;
    along.first_positive = result.counts.first_positive();
    along.soft_end = result.soft_end;
    result.energies = mode_energies(system_energy3d(packing.system), packing.x, result.computed.modes, along);
    return result;
}

// ParaView frames, one per relaxed pressure state (P_t, then the targets above it), the state index as the
// time value: the particles (whole, centres in the box) and the box, field data pressure [k_v v0] and phi.
void write_state_frames(const Jam3dResult& packing, vtk::Series& series)
{
    for (std::size_t k = 0; k < packing.states.size(); ++k) {
        if (!series.next()) continue;
        const Jam3dState& state = packing.states[k];
        DpmSystem3d at_state = packing.system;
        at_state.box = state.box;
        std::vector<vtk::Part> parts{{"particles", dpm_particles3d(at_state, state.x)},
                                     {"box", box_outline3d(state.box)}};
        for (auto& part : parts) {
            part.data.field("pressure", state.pressure);
            part.data.field("phi", state.phi);
        }
        series.write(static_cast<double>(k), parts);
    }
}

void report_packing_modes3d(const Modes3dOptions& options, const PackingModes3d& result, RunContext& context)
{
    const Jam3dResult& packing = result.packing;
    context.count_steps(packing.fire_iterations);
    if (auto* series = context.vtk()) write_state_frames(packing, *series);
    const Eigen::VectorXd& lambda = result.lambda;
    const bool every_mode = options.lowest_modes == 0;
    const SpectrumCounts counts =
        write_spectrum(lambda, packing.x.size(), result.computed.largest / packing.eigenvalue_unit,
                       options.jam.zero_threshold, context);
    const int positive = counts.first_positive();
    const auto& modes = result.computed.modes.eigenvectors;
    write_mode_energy3d(lambda, result.energies, positive, result.soft_end, context);
    write_softest_mode3d(packing.system, packing.x, result.computed.modes.eigenvalues, modes, positive,
                         context);
    // Rattlers: particles without a vertex contact (rough: vertex pairs; smooth: vertex-surface pairs); each
    // keeps the zero modes of a free particle (6 rigid motions; a floppy one N + 3, Fig. 9.15a).
    const std::vector<int> contacts = contact_counts3d(packing.system, packing.x);
    const auto rattlers = static_cast<int>(std::count(contacts.begin(), contacts.end(), 0));
    const int free_modes =
        free_particle_zero_modes(options.jam.model, packing.system.meshes[0].vertex_count(), 3);
    write_zero_mode_parts3d(packing.system, packing.x, modes.middleCols(counts.negative, counts.zero),
                            contacts, context);
    auto& summary = context.summary();
    summary["particles"] = options.jam.particles;
    summary["modes"] = lambda.size();
    summary["rattlers"] = rattlers;
    summary["zero_modes_without_rattlers"] = counts.zero - free_modes * rattlers;
    summary["spectrum_seconds"] = result.spectrum_seconds; // reported, never asserted
    // Counts over every mode: only with the dense spectrum.
    if (every_mode) {
        summary["quartic_modes"] = std::count_if(result.energies.modes.begin(), result.energies.modes.end(),
                                                 [](const ModeEnergy& mode) { return mode.quartic; });
        // zero_threshold_used <= lambda~ < soft_threshold (no mode if it lies below the threshold)
        summary["soft_modes"] = std::max(0, result.soft_end - positive);
    }
    summary["pressure_reached"] =
        pressure3d(stress_tensor3d(packing.system, packing.x)) / packing.pressure_unit;
    summary["phi"] = packing_fraction3d(packing.system, packing.x);
    summary["vertex_contacts"] = std::accumulate(contacts.begin(), contacts.end(), 0) / 2;
    summary["box_steps"] = packing.box_steps;
    summary["saddle_escapes"] = packing.saddle_escapes;
    summary["window_jumps"] = packing.window_jumps;
    summary["fire_iterations"] = packing.fire_iterations;
    summary["newton_steps"] = packing.newton_steps; // relaxation = fire_newton: the finisher's cost
    summary["newton_factorizations"] = packing.factorizations;
    summary["relax_seconds"] = packing.relax_seconds; // reported, never asserted
    summary["force_max"] = result.force_max / packing.pressure_unit;
}

// Fig. 9.15(a): a single particle relaxed from a random displacement of its mesh, and the eigenvalues of eq.
// (9.28) with unit vertex masses, in k_v v0^(4/3) = 1.
struct ParticleModes3d
{
    SingleParticle3d particle;
    Eigen::VectorXd lambda;
};

ParticleModes3d particle_modes3d(const Modes3dOptions& options)
{
    const Jam3dOptions& jam = options.jam;
    ParticleModes3d result;
    result.particle = single_particle3d_equilibrium(jam.model, mesh_from_name(jam.mesh), options.A0,
                                                    jam.stiffness, jam.seed);
    const SingleParticle3d& particle = result.particle;
    Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(particle.x.size(), particle.x.size());
    shape_energy3d(particle.shape, particle.mesh, particle.x, 0, nullptr, &hessian);
    result.lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hessian, Eigen::EigenvaluesOnly).eigenvalues();
    return result;
}

void report_particle_modes3d(const Modes3dOptions& options, const ParticleModes3d& result,
                             RunContext& context)
{
    const SingleParticle3d& particle = result.particle;
    context.count_steps(particle.fire_iterations);
    const SpectrumCounts counts =
        write_spectrum(result.lambda, result.lambda.size(), result.lambda.cwiseAbs().maxCoeff(),
                       options.jam.zero_threshold, context);
    const Eigen::VectorXd& x = particle.x;
    // ParaView: one frame, the relaxed particle (vertex diameter 1: the mesh's own unit here).
    if (auto* series = context.vtk(); series && series->next()) {
        Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
        shape_energy3d(particle.shape, particle.mesh, x, 0, &gradient, nullptr);
        series->write(0.0,
                      {{"particles",
                        mesh_particles({{&particle.mesh, 0, 1.0, particle.shape.v0, Eigen::Vector3d::Zero()}},
                                       x, gradient)}});
    }
    auto& summary = context.summary();
    summary["zero_modes_nontrivial"] = counts.zero - 6;
    summary["vertices"] = particle.mesh.vertex_count();
    summary["A_mesh"] = particle.A_mesh;
    summary["A0_used"] = particle.A0;
    summary["shape_parameter"] = mesh_shape_parameter3d(particle.mesh, x, 0);
    summary["volume"] = mesh_volume(particle.mesh, x, 0);
    summary["energy"] = shape_energy3d(particle.shape, particle.mesh, x, 0, nullptr, nullptr);
    summary["force_max"] = particle.force_max;
}

void run_modes3d(const Modes3dOptions& options, RunContext& context)
{
    context.record_seed(options.jam.seed);
    if (options.jam.particles > 1)
        report_packing_modes3d(options, packing_modes3d(options), context);
    else
        report_particle_modes3d(options, particle_modes3d(options), context);
}

} // namespace

Scene modes3d_scene()
{
    return bound_scene("dpm.modes3d",
                       "DPM eq. (9.2), (9.28): eigenvalues of the dynamical matrix of a single 3D floppy / "
                       "shell / surface-tension particle and its zero modes (Fig. 9.15a), or of a jammed "
                       "bidisperse packing of them (particles > 1, Fig. 9.15b)",
                       modes3d_binding(), run_modes3d)
        .needing(modes3d_binding().estimate([](const Modes3dOptions& options) {
            // Every mode: the dense matrix and its eigenvectors; the lowest K: the protocol's Hessian and K
            // eigenvectors of n = 3 x particles x mesh vertices.
            if (options.lowest_modes == 0)
                return packing3d_memory(options.jam.particles, options.jam.mesh, options.jam.hessian, 2);
            MemoryEstimate need =
                packing3d_memory(options.jam.particles, options.jam.mesh, options.jam.hessian, 0);
            const double n = 3.0 * options.jam.particles * mesh_from_name(options.jam.mesh).vertex_count();
            need.bytes += n * options.lowest_modes * sizeof(double);
            need.basis += ", and lowest_modes eigenvectors of 3 x particles x mesh vertices doubles";
            return need;
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
