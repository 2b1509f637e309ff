// dpm.crystal_modes: the vibrational modes (eq. 9.28) of a compressed triangular crystal of soft disks
// against its exact phonon spectrum, and the displacement field of one low-frequency mode (Fig. 9.5a).
#include "dpm/crystal_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/crystal.hpp"
#include "dpm/modes.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace softgrain::dpm {

void run_crystal_modes(const Parameters& p, RunContext& context)
{
    const int n = static_cast<int>(p.integer("rows"));
    if (n % 2 != 0)
        throw InputError("rows = " + std::to_string(n) +
                         ": a periodic triangular crystal needs an even number of rows; allowed: even >= 4");
    const double sigma = 1.0, k = 1.0, a = sigma * (1 - p.real("compression"));
    Eigen::VectorXd x;
    const DpmSystem system = triangular_crystal(n, a, sigma, k, x);
    const ModeSpectrum modes = vibrational_modes(system, x);
    const std::vector<Phonon> exact = phonon_spectrum(n, a, sigma, k);

    auto& spectrum =
        context.table("spectrum.dat", {{"k", "1", "mode index, ascending"},
                                       {"lambda", "k_c", "eigenvalue of eq. (9.28), unit masses"},
                                       {"lambda_exact", "k_c", "phonon of the lattice"},
                                       {"q", "1/sigma", "|q| of that phonon"}});
    double error = 0;
    for (std::size_t m = 0; m < exact.size(); ++m) {
        const double lambda = modes.eigenvalues(static_cast<Eigen::Index>(m));
        spectrum.row({double(m + 1), lambda, exact[m].lambda, exact[m].q.norm()});
        error = std::max(error, std::abs(lambda - exact[m].lambda));
    }
    // The mode drawn: index `mode` counted from the first non-zero one (the two translations are skipped).
    const Eigen::Index chosen = 1 + p.integer("mode");
    if (chosen >= modes.eigenvalues.size())
        throw InputError("mode = " + std::to_string(p.integer("mode")) + ": allowed 1 ... " +
                         std::to_string(modes.eigenvalues.size() - 2) + " for rows = " + std::to_string(n));
    const Eigen::VectorXd u = modes.eigenvectors.col(chosen);
    auto& field = context.table("mode.dat", {{"x", "sigma", "disk centre"},
                                             {"y", "sigma", "disk centre"},
                                             {"ux", "1", "eigenvector component (unit norm over all disks)"},
                                             {"uy", "1", "eigenvector component"}});
    for (Eigen::Index i = 0; i < u.size() / 2; ++i)
        field.row({x(2 * i), x(2 * i + 1), u(2 * i), u(2 * i + 1)});
    // One ParaView frame (time 0): the disks (vertex cells, the point order of x) with the drawn mode as the
    // point vector `mode` (unit norm over all disks; Warp By Vector animates it), the box and the contacts.
    if (auto* series = context.vtk(); series && series->next()) {
        vtk::PolyData disks = dpm_particles(system, x);
        disks.point_vectors("mode", vertex_vectors(u));
        std::vector<vtk::Part> parts{{"particles", std::move(disks)},
                                     {"box", box_outline(*system.box)},
                                     {"contacts", dpm_contacts(system, x)}};
        for (auto& part : parts) {
            part.data.field("mode_index", static_cast<double>(p.integer("mode")));
            part.data.field("lambda_mode", modes.eigenvalues(chosen));
        }
        series->write(0.0, parts);
    }

    auto& s = context.summary();
    s["spectrum_error_max"] = error;
    s["lambda_mode"] = modes.eigenvalues(chosen);
    s["lambda_mode_exact"] = exact[static_cast<std::size_t>(chosen)].lambda;
    s["q_mode"] = exact[static_cast<std::size_t>(chosen)].q.norm();
    s["participation_ratio"] = participation_ratio(u);
    s["zero_modes"] = count_zero_modes(modes.eigenvalues, zero_mode_threshold(modes.eigenvalues, 1e-13));
}

std::vector<ParameterSpec> crystal_modes_parameters()
{
    return {
        ParameterSpec::integer("rows", 12, "1", "rows of the crystal, as many disks per row (even)")
            .at_least(4),
        ParameterSpec::real("compression", 1e-3, "1", "1 - a/sigma: overlap of neighbouring disks over sigma")
            .positive()
            .below(0.5),
        ParameterSpec::integer("mode", 1, "1", "mode drawn, counted from the lowest non-zero one")
            .at_least(1),
    };
}

} // namespace softgrain::dpm
