// dpm.modes: eigenvalues of the dynamical matrix (eq. 9.28) of a single particle of Table 9.1 and the
// energy change along each mode (Figs. 9.14a, 9.14c, 9.5 single-particle analogues), or of a jammed packing
// of them (Fig. 9.14b).
#include "dpm/analysis/modes.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/mode_energy.hpp"
#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/preferred_shape.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/single_particle.hpp"
#include "dpm/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace softgrain::dpm {

namespace {

// dpm.modes's options: one particle of Table 9.1 (or a jammed packing of them, or of smooth disks) and the
// spectrum.
struct ModesOptions
{
    std::optional<ShapeModel> model = ShapeModel::floppy; // nothing: smooth bidisperse disks (packings)
    int nodes = 10;
    int particles = 1;
    double pressure = 1e-7;          // packings [k_a a0]
    std::optional<double> A0 = 1.04; // single particle; nothing: `min`, A_min(nodes)
    ShapeStiffness stiffness;        // k_a = 1 sets the energy unit k_a a0^2
    double zero_threshold = 1e-13;   // [k_a a0]
    std::uint64_t seed = 1;
    int lowest_modes = 0;                      // 0: every mode (dense)
    Relaxation relaxation = Relaxation::fire;  // packings: the dpm.jam protocol's minimiser
    double fire_step = JamOptions{}.fire_step; // packings: the dpm.jam protocol's largest FIRE step
};

OptionBinding<ModesOptions> modes_binding()
{
    const auto stiffness = [](auto field) { return path(&ModesOptions::stiffness, field); };
    OptionBinding<ModesOptions> binding;
    binding.choice(&ModesOptions::model, "model",
                   {{"floppy", ShapeModel::floppy},
                    {"shell", ShapeModel::shell},
                    {"surface_tension", ShapeModel::surface_tension},
                    {"smooth_disk", std::nullopt}},
                   "particle type of Table 9.1, or smooth bidisperse disks (packings only)");
    binding.integer(&ModesOptions::nodes, "nodes", "1", "vertices N_mu of the particle").at_least(3);
    binding
        .integer(&ModesOptions::particles, "particles", "1",
                 "1 = a single particle; more: a jammed bidisperse packing (dpm.jam protocol, nodes "
                 "and nodes + 4 vertices, stiffnesses of decision dpm-jam-polygons)")
        .at_least(1);
    binding.real(&ModesOptions::pressure, "pressure", "k_a a0", "packings: pressure of the analysed packing")
        .positive();
    binding
        .real_or_keyword(&ModesOptions::A0, "A0", "min", "1",
                         "single particle: preferred shape parameter A0 = (N l0)^2/(4 pi a0); "
                         "min = N tan(pi/N)/pi")
        .at_least(1.0);
    binding.real(stiffness(&ShapeStiffness::kl), "kl", "k_a a0", "edge stiffness k_l (floppy, shell)")
        .positive();
    binding.real(stiffness(&ShapeStiffness::kb), "kb", "k_a a0^2", "bending stiffness k_b (shell)")
        .positive();
    binding
        .real(stiffness(&ShapeStiffness::gamma), "gamma", "k_a a0^(3/2)",
              "line tension gamma (surface_tension)")
        .positive();
    binding
        .real(stiffness(&ShapeStiffness::kl_surface), "kl_surface", "k_a a0",
              "edge stiffness of the surface-tension particle (Table 9.1: ~0)")
        .non_negative();
    binding
        .real(&ModesOptions::zero_threshold, "zero_threshold", "k_a a0",
              "zero mode: lambda~ below this (Fig. 9.14a), or below the round-off bound n eps "
              "max|lambda~| where that is larger (summary zero_threshold_used)")
        .positive();
    binding.seed(&ModesOptions::seed, "seed", "seed of the random start of a floppy particle");
    binding
        .integer(
            &ModesOptions::lowest_modes, "lowest_modes", "1",
            "0: every mode by the dense eigensolver; K > 0: only the K lowest, by shift-and-invert Lanczos "
            "on "
            "the sparse dynamical matrix (large packings). With K: lambda_max from Lanczos, no "
            "quadratic_mode_exponent and no mode_parts.dat (they need every mode), and K must reach a "
            "non-zero "
            "mode (summary modes_computed)")
        .non_negative();
    bind_relaxation(binding, &ModesOptions::relaxation, "packings: the dpm.jam protocol");
    bind_fire_step(binding, &ModesOptions::fire_step);
    binding.check([](const ModesOptions& options) {
        if (options.particles > 1) return;
        if (!options.model)
            throw InputError(
                "model = smooth_disk with particles = 1: a single disk has only its translations; "
                "allowed: smooth_disk with particles > 1 (a jammed packing)");
        preferred_shape_parameter(options.A0, options.nodes); // A0 >= A_min(nodes), or min
    });
    return binding;
}

// A spectrum (eq. 9.28) takes the dense dynamical matrix and its eigenvectors: two n x n matrices.
MemoryEstimate modes_memory(const ModesOptions& options)
{
    // A packing has particles of nodes and nodes + 4 vertices, a single particle nodes.
    const double particles = options.particles;
    const double nodes = options.nodes;
    if (!options.model) return dense_matrix_memory(2 * particles, 2, "2 x particles"); // smooth disks
    const double vertices = particles > 1 ? particles * (nodes + 2) : nodes;
    return dense_matrix_memory(2 * vertices, 2, particles > 1 ? "2 x particles x (nodes + 2)" : "2 x nodes");
}

// Fig. 9.5(c, d): every non-zero mode of a packing of deformable particles (every mode of `modes`, from index
// first_positive, SpectrumCounts) split into rigid translations, rotations and deformations (decompose_mode),
// classified quartic or quadratic by Delta U (`energies`, mode_energies); the lowest-frequency quartic mode
// and the highest-frequency mode are written as fields over the packing.
void write_mode_parts(const DpmSystem& system, const Eigen::VectorXd& x, double unit,
                      const ModeSpectrum& modes, const ModeEnergies& energies, int first_positive,
                      RunContext& context)
{
    const double mixing = 0.05; // each part carries >= 5 % of |u|^2 (decision dpm-quartic-criterion)
    auto& table = context.table("mode_parts.dat",
                                {{"k", "1", "mode index, ascending eigenvalue"},
                                 {"lambda", "k_a a0", "eigenvalue lambda~_k, eq. (9.28)"},
                                 {"quartic", "1", "1 if Delta U(0.1 sigma) > 3 lambda dr^2/2 (Fig. 9.14c)"},
                                 {"translation", "1", "share of |u|^2 in rigid particle translations"},
                                 {"rotation", "1", "share of |u|^2 in rigid particle rotations"},
                                 {"deformation", "1", "share of |u|^2 in particle deformations"},
                                 {"participation_ratio", "1", "(sum |u_i|^2)^2 / (N sum |u_i|^4)"}});
    int quartic_count = 0, quartic_mixing = 0, quadratic_count = 0, quadratic_mixing = 0;
    Eigen::Index quartic_lowest = -1;
    for (Eigen::Index m = first_positive; m < modes.eigenvalues.size(); ++m) {
        const Eigen::VectorXd u = modes.eigenvectors.col(m);
        const ModeParts parts = decompose_mode(system, x, u);
        const bool quartic = energies.modes[static_cast<std::size_t>(m)].quartic;
        const bool mixes =
            parts.translation >= mixing && parts.rotation >= mixing && parts.deformation >= mixing;
        (quartic ? quartic_count : quadratic_count) += 1;
        (quartic ? quartic_mixing : quadratic_mixing) += mixes ? 1 : 0;
        if (quartic && quartic_lowest < 0) quartic_lowest = m;
        table.row({double(m + 1), modes.eigenvalues(m) / unit, quartic ? 1.0 : 0.0, parts.translation,
                   parts.rotation, parts.deformation, participation_ratio(u)});
    }
    auto& summary = context.summary();
    summary["quartic_modes"] = quartic_count;
    summary["quartic_modes_mixing_fraction"] =
        quartic_count > 0 ? nlohmann::json(double(quartic_mixing) / quartic_count) : nlohmann::json(nullptr);
    summary["quadratic_modes_mixing_fraction"] =
        quadratic_count > 0 ? nlohmann::json(double(quadratic_mixing) / quadratic_count)
                            : nlohmann::json(nullptr);
    auto& field =
        context.table("mode_fields.dat",
                      {{"panel", "1", "0 the lowest quartic mode (Fig. 9.5c), 1 the highest mode (9.5d)"},
                       {"particle", "1", "index"},
                       {"x", "sqrt(a0)", "vertex, particle shifted so its centre is in the box"},
                       {"y", "sqrt(a0)", "vertex"},
                       {"ux", "1", "mode component (unit norm over the packing)"},
                       {"uy", "1", "mode component"},
                       {"closing", "1", "1: the first vertex repeated to close the outline"}});
    const auto write_field = [&](int panel, Eigen::Index m, const std::string& prefix) {
        const Eigen::VectorXd u = modes.eigenvectors.col(m);
        const ModeParts parts = decompose_mode(system, x, u);
        summary[prefix + "_mode_index"] = m + 1;
        summary[prefix + "_lambda"] = modes.eigenvalues(m) / unit;
        summary[prefix + "_translation"] = parts.translation;
        summary[prefix + "_rotation"] = parts.rotation;
        summary[prefix + "_deformation"] = parts.deformation;
        summary[prefix + "_participation_ratio"] = participation_ratio(u);
        for (std::size_t q = 0; q < system.particles.size(); ++q) {
            const Particle& particle = system.particles[q];
            const Eigen::Map<const Eigen::Matrix2Xd> vertices(x.data() + 2 * particle.first, 2,
                                                              particle.count);
            const Eigen::Vector2d centre = vertices.rowwise().mean();
            const Eigen::Vector2d shift = wrap_into_box(centre, *system.box) - centre;
            for (int i = 0; i <= particle.count; ++i) {
                const int v = particle.first + i % particle.count;
                field.row({double(panel), double(q), x(2 * v) + shift.x(), x(2 * v + 1) + shift.y(), u(2 * v),
                           u(2 * v + 1), i == particle.count ? 1.0 : 0.0});
            }
        }
    };
    for (const char* prefix : {"quartic", "quadratic"})
        for (const char* part :
             {"_mode_index", "_lambda", "_translation", "_rotation", "_deformation", "_participation_ratio"})
            summary[std::string(prefix) + part] = nullptr;
    if (quartic_lowest >= 0) write_field(0, quartic_lowest, "quartic");
    if (first_positive < modes.eigenvalues.size()) write_field(1, modes.eigenvalues.size() - 1, "quadratic");
}

// ParaView frames of the lowest non-zero modes (at most 8, from index first_positive; --vtk-every thins
// them), one frame per mode with the mode's index k of eigenvalues.dat as the time value: the relaxed particle
// or packing (with its box and contacts) and the unit eigenvector as the point vector `mode`, so that Warp By
// Vector on `mode` shows each mode as the time slider steps through them. Field data: mode_index k and lambda
// [unit], as in eigenvalues.dat.
void write_mode_frames(const DpmSystem& system, const Eigen::VectorXd& x, const ModeSpectrum& modes,
                       int first_positive, double unit, vtk::Series& series)
{
    const Eigen::Index last = std::min<Eigen::Index>(modes.eigenvalues.size(), first_positive + 8);
    for (Eigen::Index m = first_positive; m < last; ++m) {
        if (!series.next()) continue;
        vtk::PolyData particles = dpm_particles(system, x);
        particles.point_vectors("mode", vertex_vectors(modes.eigenvectors.col(m)));
        std::vector<vtk::Part> parts{{"particles", std::move(particles)}};
        if (system.box) {
            parts.push_back({"box", box_outline(*system.box)});
            parts.push_back({"contacts", dpm_contacts(system, x)});
        }
        for (auto& part : parts) {
            part.data.field("mode_index", static_cast<double>(m + 1));
            part.data.field("lambda", modes.eigenvalues(m) / unit);
        }
        series.write(static_cast<double>(m + 1), parts);
    }
}

// The modes of a spectrum: every mode by the dense eigensolver (lowest = 0), or the `lowest` lowest by
// shift-and-invert Lanczos on the sparse matrix (sparse_modes.hpp); with max|lambda| [E/L^2] for the
// round-off bound of the zero-mode threshold (from a Lanczos run for lambda_max in the sparse case).
struct ComputedModes
{
    ModeSpectrum modes;
    double largest_magnitude = 0;
};
ComputedModes compute_modes(const DpmSystem& system, const Eigen::VectorXd& x, int lowest)
{
    if (lowest == 0) {
        ModeSpectrum modes = vibrational_modes(system, x); // exact Hessian + dense eigensolver
        const double largest = modes.eigenvalues.cwiseAbs().maxCoeff();
        return {std::move(modes), largest};
    }
    if (lowest >= x.size())
        throw InputError("lowest_modes = " + std::to_string(lowest) + " for " + std::to_string(x.size()) +
                         " degrees of freedom; allowed: 0 (every mode, dense) or 1 ... " +
                         std::to_string(x.size() - 1));
    LowestModes found = lowest_modes(sparse_dynamical_matrix(system, x), lowest);
    const double largest = std::max(std::abs(found.spectrum.eigenvalues(0)), found.largest_eigenvalue);
    return {std::move(found.spectrum), largest};
}

// The spectrum of a relaxed particle or packing: eigenvalues (eq. 9.28) in units `unit`, zero modes below
// zero_threshold, or below the round-off bound where that is larger (zero_mode_threshold), in magnitude;
// below minus that, negative modes (a saddle, decision dpm-packing-minimum). `lowest` > 0: only that many
// lowest modes (compute_modes); they must reach a non-zero mode (else the zero-mode count is incomplete:
// InputError).
struct Spectrum
{
    ComputedModes computed;
    Eigen::VectorXd lambda; // [unit]
    double threshold = 0;   // zero_threshold_used [unit]
    SpectrumCounts counts;
    double seconds = 0, seconds_min = 0; // of the first computation, and the least of its repeats
    ModeEnergies energies;               // Delta U along each mode (Fig. 9.14c), energies k_a a0^2
};

Spectrum measure_spectrum(const DpmSystem& system, const Eigen::VectorXd& x, double unit,
                          double zero_threshold, int lowest)
{
    Spectrum spectrum;
    const auto started = std::chrono::steady_clock::now();
    spectrum.computed = compute_modes(system, x, lowest);
    const ModeSpectrum& modes = spectrum.computed.modes;
    spectrum.seconds = seconds_since(started);
    // The cost chart's exponent (DPM-cost) needs the time of the algorithm, not of the other work on a shared
    // machine, which only ever adds: the least of at least 3 repeats and 0.2 s of them (at most 20).
    double spent = spectrum.seconds;
    spectrum.seconds_min = spectrum.seconds;
    for (int repeat = 1; repeat < 20 && (repeat < 3 || spent < 0.2); ++repeat) {
        const auto again = std::chrono::steady_clock::now();
        const ModeSpectrum repeated = compute_modes(system, x, lowest).modes;
        const double seconds = seconds_since(again);
        if (repeated.eigenvalues.size() != modes.eigenvalues.size())
            throw std::logic_error("measure_spectrum: a repeated spectrum changed size");
        spectrum.seconds_min = std::min(spectrum.seconds_min, seconds);
        spent += seconds;
    }
    spectrum.lambda = modes.eigenvalues / unit;
    spectrum.threshold =
        zero_mode_threshold(x.size(), spectrum.computed.largest_magnitude / unit, zero_threshold);
    spectrum.counts = count_modes(spectrum.lambda, spectrum.threshold);
    if (lowest > 0 && spectrum.counts.first_positive() >= lowest)
        throw InputError("lowest_modes = " + std::to_string(lowest) +
                         ": all of them are zero or negative modes " + "(threshold " +
                         std::to_string(spectrum.threshold) +
                         "), so the zero-mode count is incomplete; allowed: a larger lowest_modes");
    ModeEnergyOptions along;
    along.first_positive = spectrum.counts.first_positive();
    spectrum.energies = mode_energies(system_energy(system), x, modes, along);
    return spectrum;
}

// The tables eigenvalues.dat, mode_energy.dat and lowest_mode.dat, and the summary keys common to single
// particles and packings. With only the lowest modes (`lowest` > 0), lambda_max comes from Lanczos and
// quadratic_mode_exponent, a median over every non-zero mode, is not written.
void write_spectrum(const DpmSystem& system, const Eigen::VectorXd& x, double unit, int lowest,
                    const Spectrum& spectrum, RunContext& context)
{
    const ModeSpectrum& modes = spectrum.computed.modes;
    const Eigen::VectorXd& lambda = spectrum.lambda;
    const SpectrumCounts& counts = spectrum.counts;
    const int positive = counts.first_positive();
    auto& eigenvalues =
        context.table("eigenvalues.dat", {{"k", "1", "mode index, ascending eigenvalue"},
                                          {"lambda", "k_a a0", "eigenvalue lambda~_k of M, eq. (9.28)"},
                                          {"abs_lambda", "k_a a0", "|lambda~_k| (for log axes)"}});
    for (Eigen::Index m = 0; m < lambda.size(); ++m)
        eigenvalues.row({double(m + 1), lambda(m), std::abs(lambda(m))});

    auto& along =
        context.table("mode_energy.dat", {{"k", "1", "mode index"},
                                          {"lambda", "k_a a0", "eigenvalue lambda~_k"},
                                          {"zero_mode", "1", "1 if lambda~_k < zero_threshold_used"},
                                          {"dr", "sqrt(a0)", "amplitude Delta r along the unit eigenvector"},
                                          {"dU", "k_a a0^2", "Delta U = U(x + dr e_k) - U(x)"}});
    const ModeEnergies& energies = spectrum.energies;
    for (Eigen::Index m = 0; m < lambda.size(); ++m) {
        const ModeEnergy& mode = energies.modes[static_cast<std::size_t>(m)];
        for (std::size_t step = 0; step < energies.amplitudes.size(); ++step)
            along.row({double(m + 1), lambda(m), m < positive ? 1.0 : 0.0, energies.amplitudes[step],
                       mode.delta_u[step]});
    }

    auto& summary = context.summary();
    // The lowest non-zero mode (Fig. 9.5b-d): its field and how many vertices it involves.
    if (positive < lambda.size()) {
        const Eigen::VectorXd u = modes.eigenvectors.col(positive);
        auto& field = context.table("lowest_mode.dat",
                                    {{"x", "sqrt(a0) or sigma", "vertex position"},
                                     {"y", "sqrt(a0) or sigma", "vertex position"},
                                     {"ux", "1", "eigenvector of the lowest non-zero mode (unit norm)"},
                                     {"uy", "1", "eigenvector component"}});
        for (Eigen::Index i = 0; i < u.size() / 2; ++i)
            field.row({x(2 * i), x(2 * i + 1), u(2 * i), u(2 * i + 1)});
        summary["participation_ratio_lowest"] = participation_ratio(u);
    }
    if (auto* series = context.vtk()) write_mode_frames(system, x, modes, positive, unit, *series);
    summary["zero_modes"] = counts.zero;
    summary["negative_modes"] = counts.negative;
    summary["zero_threshold_used"] = spectrum.threshold;
    summary["degrees_of_freedom"] = x.size();
    summary["spectrum_seconds"] = spectrum.seconds; // cost chart (dpm-cost), reported, never asserted
    summary["spectrum_seconds_min"] =
        spectrum.seconds_min; // least of the repeats: the exponent claim of DPM-cost
    summary["lambda_smallest_nonzero"] =
        positive < lambda.size() ? nlohmann::json(lambda(positive)) : nlohmann::json(nullptr);
    summary["lambda_largest_zero"] =
        counts.zero > 0 ? nlohmann::json(lambda(positive - 1)) : nlohmann::json(nullptr);
    summary["lambda_max"] =
        lowest > 0 ? spectrum.computed.largest_magnitude / unit : lambda(lambda.size() - 1);
    summary["energy"] = energies.energy;
    const auto exponent_over = [&](int first, Eigen::Index last) {
        return value_or_null(median_exponent(energies.modes, first, last, &ModeEnergy::exponent_small));
    };
    summary["zero_mode_exponent"] = exponent_over(counts.negative, positive);
    if (lowest == 0) summary["quadratic_mode_exponent"] = exponent_over(positive, lambda.size());
    summary["modes_computed"] = lambda.size();
}

// A jammed packing (dpm.jam protocol) at the requested pressure and its spectrum (Fig. 9.14b), its forces
// first polished to round-off, as in 3D (decision dpm-zero-mode-count): FIRE leaves ~1e-10 on rattlers. A
// saddle FIRE stopped beside shows as negative modes (decision dpm-packing-minimum).
struct PackingModes
{
    JamResult packing;
    double jam_seconds = 0;
    double force_max = 0; // after the polish, k_c sigma (k_c = sigma = 1 in dpm.jam)
    Spectrum spectrum;
};

JamOptions packing_jam_options(const ModesOptions& options)
{
    JamOptions jam;
    jam.model = options.model ? jam_model(*options.model) : JamModel::smooth_disk;
    jam.particles = options.particles;
    jam.nodes_small = options.nodes;
    jam.nodes_large = options.nodes + 4;
    jam.pressure_onset = options.pressure;
    jam.pressure_max = options.pressure;
    jam.pressures = 0;
    jam.seed = options.seed;
    jam.relaxation = options.relaxation;
    jam.fire_step = options.fire_step;
    return jam;
}

PackingModes packing_modes(const ModesOptions& options)
{
    PackingModes result;
    const auto started = std::chrono::steady_clock::now();
    result.packing = jam(packing_jam_options(options));
    result.jam_seconds = seconds_since(started);
    JamResult& packing = result.packing;
    result.force_max = polish_for_modes(packing.system, packing.x, packing.pressure_unit);
    result.spectrum = measure_spectrum(packing.system, packing.x, packing.pressure_unit,
                                       options.zero_threshold, options.lowest_modes);
    return result;
}

void report_packing_modes(const ModesOptions& options, const PackingModes& result, RunContext& context)
{
    const JamResult& packing = result.packing;
    context.count_steps(packing.fire_iterations);
    write_spectrum(packing.system, packing.x, packing.pressure_unit, options.lowest_modes, result.spectrum,
                   context);
    const SpectrumCounts& counts = result.spectrum.counts;
    if (options.model && options.lowest_modes == 0) // every mode, and the highest one (Fig. 9.5d)
        write_mode_parts(packing.system, packing.x, packing.pressure_unit, result.spectrum.computed.modes,
                         result.spectrum.energies, counts.first_positive(), context);
    // Rattlers: particles whose contact forces cannot be told from zero at the polished equilibrium (also
    // those held by one contact of vanishing force, which keep 2 of their 3 rigid motions as zero modes); the
    // zero modes that move only rattlers are not the packing's own (decision dpm-zero-mode-count).
    const std::vector<bool> rattling = rattlers(packing.system, packing.x, result.force_max);
    const Eigen::MatrixXd zero_modes =
        result.spectrum.computed.modes.eigenvectors.middleCols(counts.negative, counts.zero);
    const int beyond_rattlers = zero_modes_beyond_rattlers(packing.system, zero_modes, rattling);
    auto& summary = context.summary();
    summary["rattlers"] = std::count(rattling.begin(), rattling.end(), true);
    summary["rattler_zero_modes"] = counts.zero - beyond_rattlers;
    summary["jam_seconds"] = result.jam_seconds;
    summary["fire_iterations"] = packing.fire_iterations;
    summary["newton_steps"] = packing.newton_steps; // relaxation = fire_newton: the finisher's cost
    summary["newton_factorizations"] = packing.factorizations;
    summary["zero_modes_without_rattlers"] = beyond_rattlers;
    summary["force_max"] = result.force_max;
    summary["pressure_reached"] = pressure(stress_tensor(packing.system, packing.x)) / packing.pressure_unit;
    summary["phi"] = packing_fraction(packing.system, packing.x);
}

// A single particle of Table 9.1 (area a0 = 1, the unit of area; k_a = 1 sets the energy unit k_a a0^2)
// relaxed from its random start, and its spectrum (Fig. 9.14a).
struct ParticleModes
{
    double A0 = 0; // used: A_min(nodes) for `min`
    SingleParticle particle;
    Spectrum spectrum;
};

ParticleModes particle_modes(const ModesOptions& options)
{
    const double a0 = 1.0;
    ParticleModes result;
    result.A0 = preferred_shape_parameter(options.A0, options.nodes);
    result.particle = single_particle_equilibrium(*options.model, options.nodes, a0, result.A0,
                                                  options.stiffness, options.seed);
    result.spectrum = measure_spectrum(result.particle.system, result.particle.x, options.stiffness.ka * a0,
                                       options.zero_threshold, options.lowest_modes);
    return result;
}

void report_particle_modes(const ModesOptions& options, const ParticleModes& result, RunContext& context)
{
    const SingleParticle& particle = result.particle;
    const Eigen::VectorXd& x = particle.x;
    const int n = options.nodes;
    context.count_steps(particle.fire_iterations);
    write_spectrum(particle.system, x, options.stiffness.ka, options.lowest_modes, result.spectrum, context);
    auto& summary = context.summary();
    summary["zero_modes_nontrivial"] = result.spectrum.counts.zero - 3;
    summary["A0_used"] = result.A0;
    summary["A_min"] = minimum_shape_parameter(n);
    summary["shape_parameter"] = shape_parameter(particle_perimeter(x, 0, n), particle_area(x, 0, n));
    summary["area"] = particle_area(x, 0, n);
    summary["force_max"] = particle.force_max;
}

void run_modes(const ModesOptions& options, RunContext& context)
{
    context.record_seed(options.seed);
    if (options.particles > 1)
        report_packing_modes(options, packing_modes(options), context);
    else
        report_particle_modes(options, particle_modes(options), context);
}

} // namespace

Scene modes_scene()
{
    return bound_scene(
               "dpm.modes",
               "DPM eq. (9.28): eigenvalues of the dynamical matrix of a floppy / shell / surface-tension "
               "particle, zero modes, Delta U along each mode (Figs. 9.14a, c)",
               modes_binding(), run_modes)
        .needing(modes_binding().estimate(modes_memory))
        .with_vtk();
}

} // namespace softgrain::dpm
