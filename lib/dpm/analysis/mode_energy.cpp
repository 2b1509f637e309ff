#include "dpm/analysis/mode_energy.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::dpm {

ModeEnergies mode_energies(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                           const ModeSpectrum& spectrum, const ModeEnergyOptions& options)
{
    ModeEnergies out;
    out.energy = energy(x, nullptr, nullptr) / options.energy_unit;
    // Round-off of Delta U, a difference of two energies of size |U|: an exponent needs Delta U above it.
    const double floor = 1e3 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(out.energy));
    for (int s = 0; s < options.amplitudes; ++s)
        out.amplitudes.push_back(std::pow(10.0, -3.0 + s / 8.0));
    const Eigen::Index count = spectrum.eigenvalues.size();
    out.modes.resize(static_cast<std::size_t>(count));
    for (Eigen::Index k = 0; k < count; ++k) {
        const Eigen::VectorXd mode = spectrum.eigenvectors.col(k);
        const auto change = [&](double dr) {
            return energy_change_along(energy, x, mode, dr * options.length_unit) / options.energy_unit;
        };
        ModeEnergy& record = out.modes[static_cast<std::size_t>(k)];
        for (const double dr : out.amplitudes)
            record.delta_u.push_back(change(dr));
        record.exponent_small = local_exponent(change(1e-3), change(2e-3), 1e-3, 2e-3, floor);
        if (k < options.first_positive) continue;
        if (k < options.soft_end)
            record.exponent_large = local_exponent(change(0.1), change(0.2), 0.1, 0.2, floor);
        record.quartic = quartic_energy_change(energy_change_along(energy, x, mode, 0.1),
                                               spectrum.eigenvalues(k), 0.1, 3.0);
    }
    return out;
}

std::optional<double> median_exponent(const std::vector<ModeEnergy>& modes, std::size_t first,
                                      std::size_t last, double ModeEnergy::*exponent)
{
    std::vector<double> exponents;
    for (std::size_t k = first; k < last && k < modes.size(); ++k)
        exponents.push_back(modes[k].*exponent);
    return median_exponent(std::move(exponents));
}

} // namespace softgrain::dpm
