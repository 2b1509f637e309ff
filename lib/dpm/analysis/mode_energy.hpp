// The energy change along the vibrational modes of a relaxed particle or packing, DPM sec. 9.4.3 (Figs.
// 9.14a, c in 2D, 9.15c in 3D): Delta U(dr) = U(x + dr e_k) - U(x) along each unit eigenvector e_k of the
// dynamical matrix (eq. 9.28) on a log grid of amplitudes dr; its local exponent d ln Delta U / d ln dr at
// small amplitude (quadratic modes: 2; the zero modes of a floppy particle: 4) and, on the soft modes, at
// large amplitude (quartic beyond their crossover, decision dpm-3d-quartic-window: 4); and whether a mode is
// quartic (quartic_energy_change at dr = 0.1, decision dpm-quartic-criterion). For any energy, 2D or 3D.
#pragma once

#include "dpm/analysis/modes.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace softgrain::dpm {

struct ModeEnergyOptions
{
    int amplitudes = 25;    // dr_s = 10^(-3 + s/8) length_unit, s = 0 ... amplitudes - 1 (25: 1e-3 to 1)
    double length_unit = 1; // of dr, in the units of x
    double energy_unit = 1; // of Delta U and U, in the units of the energy
    // The modes before first_positive are zero or negative modes (SpectrumCounts): no quartic test. The
    // positive ones before soft_end (of an ascending spectrum: those below a soft threshold) are soft: their
    // exponent at large amplitude is measured.
    int first_positive = 0;
    int soft_end = 0;
};

struct ModeEnergy
{
    std::vector<double> delta_u; // Delta U(dr_s) [energy_unit], one per amplitude
    // local_exponent between dr = 1e-3 and 2e-3 length_unit, and (soft modes) between 0.1 and 0.2; NaN where
    // Delta U is not above the round-off floor 1e3 eps max(1, |U|) (or not measured). A soft mode crosses from
    // quadratic to quartic at dr ~ sqrt(lambda~) <~ 1e-2 (U = lambda dr^2/2 + c dr^4 with c ~ 1); the large
    // window lies a decade beyond (decision dpm-3d-quartic-window).
    double exponent_small = std::numeric_limits<double>::quiet_NaN();
    double exponent_large = std::numeric_limits<double>::quiet_NaN();
    // Positive modes: Delta U(0.1) > 3 lambda 0.1^2 / 2, dr in the units of x (sigma) and lambda that of the
    // spectrum, as both come (decision dpm-quartic-criterion); false for the others.
    bool quartic = false;
};

struct ModeEnergies
{
    double energy = 0;              // U(x) [energy_unit]
    std::vector<double> amplitudes; // dr_s [length_unit]
    std::vector<ModeEnergy> modes;  // one per column of the spectrum, in its order
};

// The records of every mode of `spectrum` (eigenvalues in the units of the energy's Hessian, unit
// eigenvectors), at the relaxed state x.
ModeEnergies mode_energies(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                           const ModeSpectrum& spectrum, const ModeEnergyOptions& options);

// The median (median_exponent) of one exponent of the modes first ... last - 1, e.g.
// &ModeEnergy::exponent_small over the zero modes: the summaries' zero_mode_exponent, quadratic_mode_exponent
// and soft_mode_exponent_large. Nothing when each is NaN or the range is empty.
std::optional<double> median_exponent(const std::vector<ModeEnergy>& modes, std::size_t first,
                                      std::size_t last, double ModeEnergy::*exponent);

} // namespace softgrain::dpm
