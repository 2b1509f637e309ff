// Shear modulus of a jammed periodic packing, DPM section 9.4.3 (Fig. 9.16a): simple shear steps
// x'_i = x_i + dgamma y_i with Lees-Edwards boundaries (dgamma = 5e-9), an energy minimisation after each,
// shear stress Sigma~ = -Sigma_xy (eq. 9.26) and G = d Sigma~ / d gamma (least-squares slope over the steps).
// The minimisation after each step is Newton's method with the pseudo-inverse of the dynamical matrix
// (polish_newton) from the previous equilibrium: for a step of 5e-9 the quadratic model is exact to
// O(dgamma^2), so it reaches the minimum FIRE would approach, to round-off (decision dpm-shear-modulus).
// Units: G and Sigma in the stress unit of the system [E/L^2].
#pragma once

#include "dpm/system.hpp"

#include <vector>

namespace softgrain::dpm {

struct ShearModulusResult
{
    double modulus = 0;               // G [E/L^2]
    std::vector<double> shear_stress; // -Sigma_xy at gamma = 0, dgamma, 2 dgamma, ...
    double force_max = 0;             // largest force component after the last minimisation
};

// Applies `steps` strain steps of `dgamma` to a copy of the packing (which must be in equilibrium: it is
// Newton-polished first, to `force_tolerance`).
ShearModulusResult shear_modulus(DpmSystem system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance);

} // namespace softgrain::dpm
