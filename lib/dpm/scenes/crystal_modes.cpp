// dpm.crystal_modes: the vibrational modes (eq. 9.28) of a compressed triangular crystal of soft disks
// against its exact phonon spectrum, and the displacement field of one low-frequency mode (Fig. 9.5a).
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/scenes/scenes.hpp"
#include "dpm/system/crystal.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace softgrain::dpm {

namespace {

struct CrystalModesOptions
{
    int rows = 12;
    double compression = 1e-3; // 1 - a/sigma
    int mode = 1;              // counted from the lowest non-zero mode
};

OptionBinding<CrystalModesOptions> crystal_modes_binding()
{
    OptionBinding<CrystalModesOptions> binding;
    binding
        .integer(&CrystalModesOptions::rows, "rows", "1", "rows of the crystal, as many disks per row (even)")
        .at_least(4);
    binding
        .real(&CrystalModesOptions::compression, "compression", "1",
              "1 - a/sigma: overlap of neighbouring disks over sigma")
        .positive()
        .below(0.5);
    binding
        .integer(&CrystalModesOptions::mode, "mode", "1", "mode drawn, counted from the lowest non-zero one")
        .at_least(1);
    binding.check([](const CrystalModesOptions& options) {
        if (options.rows % 2 != 0)
            throw InputError(
                "rows = " + std::to_string(options.rows) +
                ": a periodic triangular crystal needs an even number of rows; allowed: even >= 4");
        // rows^2 disks: 2 rows^2 modes, of which the first two are the translations.
        const long long modes = 2LL * options.rows * options.rows;
        if (options.mode + 1LL >= modes)
            throw InputError("mode = " + std::to_string(options.mode) + ": allowed 1 ... " +
                             std::to_string(modes - 2) + " for rows = " + std::to_string(options.rows));
    });
    return binding;
}

// The crystal's modes (unit masses), its exact phonons, and the mode drawn.
struct CrystalModesResult
{
    DpmSystem system;
    Eigen::VectorXd x;
    ModeSpectrum modes;
    std::vector<Phonon> exact; // ascending, as the modes
    Eigen::Index chosen = 0;   // column of the mode drawn: `mode` counted past the two translations
};

CrystalModesResult crystal_modes(const CrystalModesOptions& options)
{
    const double sigma = 1.0, k = 1.0, a = sigma * (1 - options.compression);
    CrystalModesResult result;
    result.system = triangular_crystal(options.rows, a, sigma, k, result.x);
    result.modes = vibrational_modes(result.system, result.x);
    result.exact = phonon_spectrum(options.rows, a, sigma, k);
    result.chosen = 1 + options.mode;
    return result;
}

// One ParaView frame (time 0): the disks (vertex cells, the point order of x) with the drawn mode as the
// point vector `mode` (unit norm over all disks; Warp By Vector animates it), the box and the contacts.
void write_mode_frame(const CrystalModesResult& result, int mode, vtk::Series& series)
{
    vtk::PolyData disks = dpm_particles(result.system, result.x);
    disks.point_vectors("mode", vertex_vectors(result.modes.eigenvectors.col(result.chosen)));
    std::vector<vtk::Part> parts{{"particles", std::move(disks)},
                                 {"box", box_outline(*result.system.box)},
                                 {"contacts", dpm_contacts(result.system, result.x)}};
    for (auto& part : parts) {
        part.data.field("mode_index", static_cast<double>(mode));
        part.data.field("lambda_mode", result.modes.eigenvalues(result.chosen));
    }
    series.write(0.0, parts);
}

void report_crystal_modes(const CrystalModesOptions& options, const CrystalModesResult& result,
                          RunContext& context)
{
    const Eigen::VectorXd& lambda = result.modes.eigenvalues;
    auto& spectrum =
        context.table("spectrum.dat", {{"k", "1", "mode index, ascending"},
                                       {"lambda", "k_c", "eigenvalue of eq. (9.28), unit masses"},
                                       {"lambda_exact", "k_c", "phonon of the lattice"},
                                       {"q", "1/sigma", "|q| of that phonon"}});
    double error = 0;
    for (std::size_t m = 0; m < result.exact.size(); ++m) {
        const double computed = lambda(static_cast<Eigen::Index>(m));
        spectrum.row({double(m + 1), computed, result.exact[m].lambda, result.exact[m].q.norm()});
        error = std::max(error, std::abs(computed - result.exact[m].lambda));
    }
    const Eigen::VectorXd u = result.modes.eigenvectors.col(result.chosen);
    auto& field = context.table("mode.dat", {{"x", "sigma", "disk centre"},
                                             {"y", "sigma", "disk centre"},
                                             {"ux", "1", "eigenvector component (unit norm over all disks)"},
                                             {"uy", "1", "eigenvector component"}});
    for (Eigen::Index i = 0; i < u.size() / 2; ++i)
        field.row({result.x(2 * i), result.x(2 * i + 1), u(2 * i), u(2 * i + 1)});
    if (auto* series = context.vtk(); series && series->next())
        write_mode_frame(result, options.mode, *series);

    const Phonon& drawn = result.exact[static_cast<std::size_t>(result.chosen)];
    auto& summary = context.summary();
    summary["spectrum_error_max"] = error;
    summary["lambda_mode"] = lambda(result.chosen);
    summary["lambda_mode_exact"] = drawn.lambda;
    summary["q_mode"] = drawn.q.norm();
    summary["participation_ratio"] = participation_ratio(u);
    summary["zero_modes"] = count_zero_modes(lambda, zero_mode_threshold(lambda, 1e-13));
}

void run_crystal_modes(const CrystalModesOptions& options, RunContext& context)
{
    report_crystal_modes(options, crystal_modes(options), context);
}

} // namespace

Scene crystal_modes_scene()
{
    return bound_scene(
               "dpm.crystal_modes",
               "DPM eq. (9.28), Fig. 9.5(a): modes of a compressed triangular soft-disk crystal against "
               "its exact phonon spectrum; the displacement field of one mode",
               crystal_modes_binding(), run_crystal_modes)
        .needing(crystal_modes_binding().estimate([](const CrystalModesOptions& options) {
            // rows x rows disks: the dynamical matrix of 2 rows^2 rows and its eigenvectors.
            const double rows = options.rows;
            return dense_matrix_memory(2 * rows * rows, 2, "2 x rows^2");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
