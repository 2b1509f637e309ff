// The scaling analysis of Rognon & Gay (Fig. 3a, b) for the paper's laws (eqs. 3-5, F_adh = 0), and the
// local exponents measured on a simulated approach (Fig. 3d, f).
//
// Constant force, balanced state (eq. 1): (delta/R)^2 (h-bar/R + delta/R) = kappa^2/(2 alpha^2), so along the
// approach delta = delta(h) and h-dot = -(F/zeta) ~ h-bar^3/(h-bar + delta)^2. Differentiating in ln h gives
// the exact local exponents (derived here, not printed in the paper):
//   lambda1 = d ln delta/d ln h = -g/(2 h-bar + 3 delta),  g = h dh-bar/dh = h R^2/(R + h)^2,
//   lambda2 = d ln|h-dot|/d ln h = 3 g/h-bar - 2 (g + lambda1 delta)/(h-bar + delta).
// Their regime limits are the exponents of Fig. 3a: lambda2 = 0, 1, 3 and lambda1 = 0, -1/2, 0 (Stokes,
// Poiseuille, Hertz), and expanding to first order in the small ratios gives the width of each regime:
//   Stokes (h >> R):               lambda2 = (R/h)(3 - 2R/(R + delta)) + ..., w_S = (R/h)(3 - 2R/(R + delta))
//   Poiseuille (delta << h << R):  lambda2 = 1 - h/R + 3 delta/h + ...,       w_P = h/R + 3 delta/h
//   Hertz (h << delta, h << R):    lambda2 = 3 - 3h/R - (4/3) h/delta + ...,  w_H = 3h/R + (4/3) h/delta
// with |lambda1 - limit| <= w/2 in each case. The Poiseuille-Hertz crossover delta = h sits at
//   kappa = alpha sqrt(2) (h/R) sqrt(h-bar/R + h/R) -> 2 alpha (h/R)^(3/2) for h << R
// (the paper: kappa ~ (h/R)^(3/2)).
#pragma once

#include "sd/approach.hpp"
#include "sd/contact_laws.hpp"

#include <vector>

namespace softgrain::sd {

struct LocalExponents
{
    std::vector<double> lambda1; // d ln delta / d ln h at each sample
    std::vector<double> lambda2; // d ln|h-dot| / d ln h at each sample
};

// Three-point differences on the (non-uniform) ln h grid of the samples; one-sided at the ends.
// Second-order accurate in the ln h spacing.
LocalExponents local_exponents(const std::vector<ApproachSample>& samples);

// The exact exponents above, at gap h and balanced deflection delta, for the paper's laws.
double lambda1_paper(const Material& m, double h, double delta);
double lambda2_paper(const Material& m, double h, double delta);

enum class Regime { stokes, poiseuille, hertz };
// The first-order deviation w of lambda2 from its regime limit (see above); lambda1's is w/2.
double regime_width(Regime regime, double R, double h, double delta);
double lambda1_limit(Regime regime); // 0, -1/2, 0
double lambda2_limit(Regime regime); // 0, 1, 3

// kappa at which delta = h (Poiseuille-Hertz crossover) for the paper's laws, exact and its h << R limit.
double crossover_kappa_paper(const Material& m, double h);
double crossover_kappa_asymptotic(const Material& m, double h);

// Balanced deflection of the paper's laws in closed form: the positive root of the cubic
// (delta/R)^2 (h-bar/R + delta/R) = kappa^2/(2 alpha^2), kappa = F/(E R^2). Independent of the Brent solver.
double balanced_deflection_paper(const Material& m, double h, double force);

} // namespace softgrain::sd
