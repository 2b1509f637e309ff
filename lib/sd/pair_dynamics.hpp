// Soft Dynamics of one pair (Rognon & Gay, Fig. 4): from the centre distance X and the gap h to their rates.
//
//   (X, h) -> delta (eq. 2) -> a(h, delta) (eq. 5) -> zeta (eq. 4), C and D (from eq. 8)
//          -> h-dot (eq. 7) and X-dot (eq. 9), given F_ext and dF_ext/dt.
//
// Units: lengths in m, forces in N, rates in m/s. Sign: F_ext > 0 pushes the particles together; h-dot < 0
// while the gap closes. No inertia (Stokes regime).
// Valid for a gap h > 0 (the lubrication friction zeta of eq. (4) diverges at contact), deflections
// 0 <= delta < R (eq. (2) with the laws of contact_laws.hpp) and equal spheres of radius R.
#pragma once

#include "sd/contact_laws.hpp"

#include <functional>

namespace softgrain::sd {

// SD eq. (2): X = 2R + h - 2 delta, solved for the deflection delta (m).
double deflection_eq2(double radius, double X, double h);

// Every intermediate quantity of Fig. 4 at one state.
struct PairRates
{
    double delta = 0; // eq. (2) (m)
    double a = 0;     // eq. (5) (m)
    double zeta = 0;  // eq. (4) (N s/m)
    double C = 0;     // script C = (F_a a_delta + F_delta)/2, stiffness of the X dynamics (N/m)
    double D = 0;     // script D = C zeta / (C + F_a a_h), friction of the X dynamics (N s/m)
    double F_ela = 0; // eq. (3) at (a, delta) (N)
    double F_adh = 0; // remote force (N)
    double h_dot = 0; // eq. (7): -(F_ext - F_adh)/zeta (m/s)
    double X_dot = 0; // eq. (9): -dF_ext/dt / C - (F_ext - F_adh)/D (m/s)
};

// The Soft Dynamics rates of eqs. (7) and (9). F_ext is the force transmitted by the pair (N), F_ext_rate its
// time derivative (N/s). Requires h > 0 (zeta diverges at contact).
PairRates soft_dynamics_rates(const ContactLaws& laws, double radius, double X, double h, double F_ext,
                              double F_ext_rate);

// The deflection that satisfies the force balance eq. (1), F_ela(a(h, delta), delta) = F_ext, at gap h (m).
// Brent's method (GSL) on [0, delta_max], with delta_max grown until it brackets the root; F_ext >= 0 and
// F_ela increasing in delta are assumed (true of eqs. 3, 5). Relative accuracy ~1e-14.
double balanced_deflection(const ContactLaws& laws, double h, double F_ext);

// An external force history F_ext(t) with its derivative (N, N/s); constant by default.
struct Loading
{
    std::function<double(double)> force;
    std::function<double(double)> rate;
};
Loading constant_loading(double force);

} // namespace softgrain::sd
