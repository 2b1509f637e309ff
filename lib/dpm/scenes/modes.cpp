// dpm.modes: eigenvalues of the dynamical matrix (eq. 9.28) of a single particle of Table 9.1 and the
// energy change along each mode (Figs. 9.14a, 9.14c, 9.5 single-particle analogues).
#include "dpm/modes_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/jam.hpp"
#include "dpm/modes.hpp"
#include "dpm/preferred_shape.hpp"
#include "dpm/single_particle.hpp"
#include "dpm/sparse_modes.hpp"
#include "dpm/stress.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace softgrain::dpm {

namespace {

// Fig. 9.5(c, d): every non-zero mode of a packing of deformable particles split into rigid translations,
// rotations and deformations (decompose_mode), classified quartic or quadratic by Delta U (is_quartic_mode);
// the lowest-frequency quartic mode and the highest-frequency mode are written as fields over the packing.
// The positive modes start at index first_positive (SpectrumCounts).
void write_mode_parts(const DpmSystem& system, const Eigen::VectorXd& x, double unit, int first_positive,
                      RunContext& context)
{
    const ModeSpectrum modes = vibrational_modes(system, x);
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
        const bool quartic = is_quartic_mode(system, x, u, modes.eigenvalues(m), 0.1, 3.0);
        const bool mixes =
            parts.translation >= mixing && parts.rotation >= mixing && parts.deformation >= mixing;
        (quartic ? quartic_count : quadratic_count) += 1;
        (quartic ? quartic_mixing : quadratic_mixing) += mixes ? 1 : 0;
        if (quartic && quartic_lowest < 0) quartic_lowest = m;
        table.row({double(m + 1), modes.eigenvalues(m) / unit, quartic ? 1.0 : 0.0, parts.translation,
                   parts.rotation, parts.deformation, participation_ratio(u)});
    }
    auto& s = context.summary();
    s["quartic_modes"] = quartic_count;
    s["quartic_modes_mixing_fraction"] =
        quartic_count > 0 ? nlohmann::json(double(quartic_mixing) / quartic_count) : nlohmann::json(nullptr);
    s["quadratic_modes_mixing_fraction"] = quadratic_count > 0
                                               ? nlohmann::json(double(quadratic_mixing) / quadratic_count)
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
        s[prefix + "_mode_index"] = m + 1;
        s[prefix + "_lambda"] = modes.eigenvalues(m) / unit;
        s[prefix + "_translation"] = parts.translation;
        s[prefix + "_rotation"] = parts.rotation;
        s[prefix + "_deformation"] = parts.deformation;
        s[prefix + "_participation_ratio"] = participation_ratio(u);
        for (std::size_t q = 0; q < system.particles.size(); ++q) {
            const Particle& p = system.particles[q];
            const Eigen::Map<const Eigen::Matrix2Xd> r(x.data() + 2 * p.first, 2, p.count);
            const Eigen::Vector2d c = r.rowwise().mean();
            const Eigen::Vector2d shift = wrap_into_box(c, *system.box) - c;
            for (int i = 0; i <= p.count; ++i) {
                const int v = p.first + i % p.count;
                field.row({double(panel), double(q), x(2 * v) + shift.x(), x(2 * v + 1) + shift.y(), u(2 * v),
                           u(2 * v + 1), i == p.count ? 1.0 : 0.0});
            }
        }
    };
    for (const char* prefix : {"quartic", "quadratic"})
        for (const char* part :
             {"_mode_index", "_lambda", "_translation", "_rotation", "_deformation", "_participation_ratio"})
            s[std::string(prefix) + part] = nullptr;
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

} // namespace

nlohmann::json median_or_null(std::vector<double> values)
{
    values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
                 values.end());
    if (values.empty()) return nullptr;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The modes write_spectrum reads: every mode by the dense eigensolver (lowest = 0), or the `lowest` lowest
// by shift-and-invert Lanczos on the sparse matrix (sparse_modes.hpp); with max|lambda| [E/L^2] for the
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

// Eigenvalues (eq. 9.28) in units `unit`, the tables eigenvalues.dat and mode_energy.dat, and the summary
// keys common to single particles and packings. Zero modes: below zero_threshold, or below the round-off
// bound where that is larger (zero_mode_threshold), in magnitude; below minus that, negative modes (a
// saddle, decision dpm-packing-minimum). `lowest` > 0: only that many lowest modes (compute_modes); they
// must reach a non-zero mode (else the zero-mode count is incomplete: InputError), lambda_max comes from
// Lanczos, and quadratic_mode_exponent, a median over every non-zero mode, is not written. Returns the
// counts and the zero modes.
struct WrittenSpectrum
{
    SpectrumCounts counts;
    Eigen::MatrixXd zero_modes; // orthonormal columns
};
WrittenSpectrum write_spectrum(const DpmSystem& system, const Eigen::VectorXd& x, double unit,
                               double zero_threshold, int lowest, RunContext& context)
{
    const auto started = std::chrono::steady_clock::now();
    const ComputedModes computed = compute_modes(system, x, lowest);
    const ModeSpectrum& modes = computed.modes;
    const double spectrum_seconds = seconds_since(started);
    // The cost chart's exponent (DPM-cost) needs the time of the algorithm, not of the other work on a shared
    // machine, which only ever adds: the least of at least 3 repeats and 0.2 s of them (at most 20).
    double spectrum_seconds_min = spectrum_seconds, spent = spectrum_seconds;
    for (int repeat = 1; repeat < 20 && (repeat < 3 || spent < 0.2); ++repeat) {
        const auto again = std::chrono::steady_clock::now();
        const ModeSpectrum repeated = compute_modes(system, x, lowest).modes;
        const double seconds = seconds_since(again);
        if (repeated.eigenvalues.size() != modes.eigenvalues.size())
            throw std::logic_error("write_spectrum: a repeated spectrum changed size");
        spectrum_seconds_min = std::min(spectrum_seconds_min, seconds);
        spent += seconds;
    }
    const Eigen::VectorXd lambda = modes.eigenvalues / unit;
    const double threshold = zero_mode_threshold(x.size(), computed.largest_magnitude / unit, zero_threshold);
    const SpectrumCounts counts = count_modes(lambda, threshold);
    const int positive = counts.first_positive();
    if (lowest > 0 && positive >= lowest)
        throw InputError("lowest_modes = " + std::to_string(lowest) +
                         ": all of them are zero or negative modes " + "(threshold " +
                         std::to_string(threshold) +
                         "), so the zero-mode count is incomplete; allowed: a larger lowest_modes");

    auto& spectrum =
        context.table("eigenvalues.dat", {{"k", "1", "mode index, ascending eigenvalue"},
                                          {"lambda", "k_a a0", "eigenvalue lambda~_k of M, eq. (9.28)"},
                                          {"abs_lambda", "k_a a0", "|lambda~_k| (for log axes)"}});
    for (Eigen::Index m = 0; m < lambda.size(); ++m)
        spectrum.row({double(m + 1), lambda(m), std::abs(lambda(m))});

    auto& along =
        context.table("mode_energy.dat", {{"k", "1", "mode index"},
                                          {"lambda", "k_a a0", "eigenvalue lambda~_k"},
                                          {"zero_mode", "1", "1 if lambda~_k < zero_threshold_used"},
                                          {"dr", "sqrt(a0)", "amplitude Delta r along the unit eigenvector"},
                                          {"dU", "k_a a0^2", "Delta U = U(x + dr e_k) - U(x)"}});
    const double u0 = total_energy(system, x, nullptr, nullptr);
    const double floor = 1e3 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(u0));
    std::vector<double> zero_exponents, quadratic_exponents;
    for (Eigen::Index m = 0; m < lambda.size(); ++m) {
        const Eigen::VectorXd e = modes.eigenvectors.col(m);
        for (int s = 0; s <= 24; ++s) {
            const double dr = std::pow(10.0, -3.0 + s / 8.0);
            along.row({double(m + 1), lambda(m), m < positive ? 1.0 : 0.0, dr,
                       energy_change_along(system, x, e, dr)});
        }
        const double exponent = local_exponent(energy_change_along(system, x, e, 1e-3),
                                               energy_change_along(system, x, e, 2e-3), 1e-3, 2e-3, floor);
        if (m >= counts.negative) (m < positive ? zero_exponents : quadratic_exponents).push_back(exponent);
    }

    auto& s = context.summary();
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
        s["participation_ratio_lowest"] = participation_ratio(u);
    }
    if (auto* series = context.vtk()) write_mode_frames(system, x, modes, positive, unit, *series);
    s["zero_modes"] = counts.zero;
    s["negative_modes"] = counts.negative;
    s["zero_threshold_used"] = threshold;
    s["degrees_of_freedom"] = x.size();
    s["spectrum_seconds"] = spectrum_seconds;         // cost chart (dpm-cost), reported, never asserted
    s["spectrum_seconds_min"] = spectrum_seconds_min; // least of the repeats: the exponent claim of DPM-cost
    s["lambda_smallest_nonzero"] =
        positive < lambda.size() ? nlohmann::json(lambda(positive)) : nlohmann::json(nullptr);
    s["lambda_largest_zero"] =
        counts.zero > 0 ? nlohmann::json(lambda(positive - 1)) : nlohmann::json(nullptr);
    s["lambda_max"] = lowest > 0 ? computed.largest_magnitude / unit : lambda(lambda.size() - 1);
    s["energy"] = u0;
    s["zero_mode_exponent"] = median_or_null(zero_exponents);
    if (lowest == 0) s["quadratic_mode_exponent"] = median_or_null(quadratic_exponents);
    s["modes_computed"] = lambda.size();
    return {counts, modes.eigenvectors.middleCols(counts.negative, counts.zero)};
}

// A jammed packing (dpm.jam protocol) at the requested pressure and its spectrum (Fig. 9.14b).
void run_packing_modes(const Parameters& p, RunContext& context)
{
    JamOptions o;
    o.model = p.choice("model");
    o.particles = static_cast<int>(p.integer("particles"));
    o.nodes_small = static_cast<int>(p.integer("nodes"));
    o.nodes_large = o.nodes_small + 4;
    o.pressure_onset = p.real("pressure");
    o.pressure_max = o.pressure_onset;
    o.pressures = 0;
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(o.seed);
    const auto started = std::chrono::steady_clock::now();
    JamResult r = jam(o);
    const double jam_seconds = seconds_since(started);
    context.count_steps(r.fire_iterations);
    // Forces to round-off first, as in 3D (decision dpm-zero-mode-count): FIRE leaves ~1e-10 on rattlers.
    // A saddle FIRE stopped beside shows as negative modes (decision dpm-packing-minimum).
    const double zero_threshold = p.real("zero_threshold");
    const double force_max = polish_for_modes(r.system, r.x, r.pressure_unit);
    const int lowest = static_cast<int>(p.integer("lowest_modes"));
    const WrittenSpectrum spectrum =
        write_spectrum(r.system, r.x, r.pressure_unit, zero_threshold, lowest, context);
    if (o.model != "smooth_disk" && lowest == 0) // every mode, and the highest one (Fig. 9.5d)
        write_mode_parts(r.system, r.x, r.pressure_unit, spectrum.counts.first_positive(), context);
    // Rattlers: particles whose contact forces cannot be told from zero at the polished equilibrium (also
    // those held by one contact of vanishing force, which keep 2 of their 3 rigid motions as zero modes); the
    // zero modes that move only rattlers are not the packing's own (decision dpm-zero-mode-count).
    const std::vector<bool> rattling = rattlers(r.system, r.x, force_max);
    const int beyond_rattlers = zero_modes_beyond_rattlers(r.system, spectrum.zero_modes, rattling);
    auto& s = context.summary();
    s["rattlers"] = std::count(rattling.begin(), rattling.end(), true);
    s["rattler_zero_modes"] = spectrum.counts.zero - beyond_rattlers;
    s["jam_seconds"] = jam_seconds;
    s["fire_iterations"] = r.fire_iterations;
    s["zero_modes_without_rattlers"] = beyond_rattlers;
    s["force_max"] = force_max; // after the polish, k_c sigma (k_c = sigma = 1 in dpm.jam)
    s["pressure_reached"] = pressure(stress_tensor(r.system, r.x)) / r.pressure_unit;
    s["phi"] = packing_fraction(r.system, r.x);
}

void run_modes(const Parameters& p, RunContext& context)
{
    if (p.integer("particles") > 1) {
        run_packing_modes(p, context);
        return;
    }
    if (p.choice("model") == "smooth_disk")
        throw InputError("model = smooth_disk with particles = 1: a single disk has only its translations; "
                         "allowed: smooth_disk with particles > 1 (a jammed packing)");
    const int n = static_cast<int>(p.integer("nodes"));
    const ShapeModel model = shape_model_from_name(p.choice("model"));
    const double a_min = minimum_shape_parameter(n);
    const double A0 = preferred_shape_parameter(p, "A0", n);
    const double a0 = 1.0; // unit of area; k_a = 1 sets the energy unit k_a a0^2
    ShapeStiffness k;
    k.ka = 1.0;
    k.kl = p.real("kl");
    k.kb = p.real("kb");
    k.gamma = p.real("gamma");
    k.kl_surface = p.real("kl_surface");

    const auto seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(seed);
    const SingleParticle particle = single_particle_equilibrium(model, n, a0, A0, k, seed);
    const DpmSystem& system = particle.system;
    const Eigen::VectorXd& x = particle.x;
    const double force = particle.force_max;
    context.count_steps(particle.fire_iterations);

    const int zero = write_spectrum(system, x, k.ka * a0, p.real("zero_threshold"),
                                    static_cast<int>(p.integer("lowest_modes")), context)
                         .counts.zero;
    auto& s = context.summary();
    s["zero_modes_nontrivial"] = zero - 3;
    s["A0_used"] = A0;
    s["A_min"] = a_min;
    s["shape_parameter"] = shape_parameter(particle_perimeter(x, 0, n), particle_area(x, 0, n));
    s["area"] = particle_area(x, 0, n);
    s["force_max"] = force;
}

std::vector<ParameterSpec> modes_parameters()
{
    return {
        ParameterSpec::choice("model", "floppy", {"floppy", "shell", "surface_tension", "smooth_disk"},
                              "particle type of Table 9.1, or smooth bidisperse disks (packings only)"),
        ParameterSpec::integer("nodes", 10, "1", "vertices N_mu of the particle").at_least(3),
        ParameterSpec::integer(
            "particles", 1, "1",
            "1 = a single particle; more: a jammed bidisperse packing (dpm.jam protocol, nodes "
            "and nodes + 4 vertices, stiffnesses of decision dpm-jam-polygons)")
            .at_least(1),
        ParameterSpec::real("pressure", 1e-7, "k_a a0", "packings: pressure of the analysed packing")
            .positive(),
        preferred_shape_parameter_spec(1.04, false,
                                       "single particle: preferred shape parameter A0 = (N l0)^2/(4 pi a0); "
                                       "min = N tan(pi/N)/pi"),
        ParameterSpec::real("kl", 1.0, "k_a a0", "edge stiffness k_l (floppy, shell)").positive(),
        ParameterSpec::real("kb", 1.0, "k_a a0^2", "bending stiffness k_b (shell)").positive(),
        ParameterSpec::real("gamma", 0.1, "k_a a0^(3/2)", "line tension gamma (surface_tension)").positive(),
        ParameterSpec::real("kl_surface", 0.0, "k_a a0",
                            "edge stiffness of the surface-tension particle (Table 9.1: ~0)")
            .non_negative(),
        ParameterSpec::real("zero_threshold", 1e-13, "k_a a0",
                            "zero mode: lambda~ below this (Fig. 9.14a), or below the round-off bound n eps "
                            "max|lambda~| where that is larger (summary zero_threshold_used)")
            .positive(),
        ParameterSpec::seed("seed", 1, "seed of the random start of a floppy particle"),
        ParameterSpec::integer(
            "lowest_modes", 0, "1",
            "0: every mode by the dense eigensolver; K > 0: only the K lowest, by shift-and-invert Lanczos "
            "on "
            "the sparse dynamical matrix (large packings). With K: lambda_max from Lanczos, no "
            "quadratic_mode_exponent and no mode_parts.dat (they need every mode), and K must reach a "
            "non-zero "
            "mode (summary modes_computed)")
            .non_negative(),
    };
}

} // namespace softgrain::dpm
