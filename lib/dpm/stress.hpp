// Stress tensor of a static periodic packing of deformable particles, DPM eqs. (9.25)-(9.26):
//
//   Sigma_ab = (1/A) [ sum_mu sum_i r~_{mu i,a} F^shape_{mu i,b} - sum_{pairs} r_{mu i,beta j,a} F_{mu i,beta
//   j,b} ]
//
// A = L_x L_y; shape forces F^shape = -grad U_shape at the unwrapped vertices of each particle (the copy
// used to evaluate the shape energy); interaction force moments at the minimum-image coordinates each
// contact term is evaluated with (rough pairs, and the smooth vertex-edge terms, section 9.4.2). Kinetic
// terms vanish for static packings. Sign: positive in compression; pressure P = Tr(Sigma)/2.
// Units [E/L^2]. Anchors (external constraints) are not part of the stress.
#pragma once

#include "dpm/system.hpp"

namespace softgrain::dpm {

Eigen::Matrix2d stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x);

inline double pressure(const Eigen::Matrix2d& stress)
{
    return 0.5 * stress.trace();
}

} // namespace softgrain::dpm
