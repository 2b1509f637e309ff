// SPD calibration (Trivino et al., section 3 and section 4.1): force-law parameters from the shell material,
// the shell and effective bulk moduli, and the characteristic scales of diametral compression.
//
// Units: SI. E, sigma_Y [Pa]; h, s, l, R [m]. As printed, eqs. (10)-(11) make k_s a spring stiffness [N/m]
// and k_b a hinge stiffness [N m / rad] that do not depend on s or on the segment length l: the discrete
// flexural rigidity of a chain of hinges a distance l apart is EI_eff = k_b l = E I_c / (1 - nu^2) with the
// paper's I_c = h^3 l / 12 (decision spd-Ic-width). Compression is counted positive (section 2.2).
#pragma once

#include <cmath>
#include <numbers>

namespace softgrain::spd {

// Shell material and geometry: Young modulus E, Poisson ratio nu, thickness h, out-of-plane length s,
// tensile plastic stress sigma_Y (infinite for a purely elastic shell).
struct ShellMaterial
{
    double E = 0, nu = 0, h = 0, s = 0, sigma_Y = INFINITY;
};

// Parameters of the shell force laws: stretch stiffness k_s [N/m], bending stiffness k_b [N m],
// plastic thresholds F_s^Y [N] and M_b^Y [N m] (infinite when sigma_Y is).
struct ShellLaws
{
    double k_s = 0, k_b = 0, F_Y = INFINITY, M_Y = INFINITY;
};

// SPD eqs. (10)-(13): k_s = E h/(1-nu^2), k_b = E h^3/(12(1-nu^2)), F_s^Y = h s sigma_Y,
// M_b^Y = 4 I_c sigma_Y / h with I_c = h^3 l / 12, l the segment length. Valid for 0 <= nu < 1.
inline ShellLaws calibrate(const ShellMaterial& m, double l)
{
    const double plate = m.E / (1.0 - m.nu * m.nu);
    const double I_c = m.h * m.h * m.h * l / 12.0;
    return {plate * m.h, plate * m.h * m.h * m.h / 12.0, m.h * m.s * m.sigma_Y, 4.0 * I_c * m.sigma_Y / m.h};
}

// Inverse of eqs. (10)-(13) for a given nu, s and l: h = sqrt(12 k_b/k_s), E = k_s (1-nu^2)/h,
// sigma_Y = F_s^Y/(h s). The thresholds are not independent: eqs. (12)-(13) imply M_b^Y = F_s^Y h l/(3 s);
// the inverse uses F_s^Y and leaves that consistency to the caller.
inline ShellMaterial material_from_laws(const ShellLaws& laws, double nu, double s)
{
    const double h = std::sqrt(12.0 * laws.k_b / laws.k_s);
    return {laws.k_s * (1.0 - nu * nu) / h, nu, h, s, laws.F_Y / (h * s)};
}

// SPD eq. (23), exact form: K_shell = (k_s/s) tan(pi/N) [Pa] for a regular N-gon ring (the printed
// approximation "2 pi/(N s) ..." is a factor 2 too large, decision spd-eq23-factor).
inline double shell_bulk_modulus(double k_s, double s, int N)
{
    return k_s / s * std::tan(std::numbers::pi / N);
}

// SPD eq. (24)-(25): eta = K_Omega/K_shell and K_e = (1 + eta) K_shell [Pa].
inline double core_to_shell_ratio(double K_Omega, double K_shell)
{
    return K_Omega / K_shell;
}
inline double effective_bulk_modulus(double eta, double K_shell)
{
    return (1.0 + eta) * K_shell;
}

// Characteristic scales of diametral compression, eqs. (30)-(37), with R the initial radius R0:
//   F* = k_b/R (30),  M* = F* l (32),  F** = M^Y/l (33),
//   p* = F*/(s l),  p** = F**/(s l),  sigma* = F*/(2 R s) (37).
struct CharacteristicScales
{
    double F_star, M_star, F_2star, p_star, p_2star, sigma_star;
};
inline CharacteristicScales characteristic_scales(double k_b, double M_Y, double R, double l, double s)
{
    const double F_star = k_b / R;
    const double F_2star = M_Y / l;
    return {F_star, F_star * l, F_2star, F_star / (s * l), F_2star / (s * l), F_star / (2.0 * R * s)};
}

} // namespace softgrain::spd
