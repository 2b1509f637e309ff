// Stress tensor of a static periodic packing of deformable particles, DPM eqs. (9.25)-(9.26):
//
//   Sigma_ab = (1/A) [ sum_mu sum_i r~_{mu i,a} F^shape_{mu i,b}
//                      - sum_{pairs} r_{mu i,beta j,a} F_{mu i,beta j,b} ]
//
// A = L_x L_y; shape forces F^shape = -grad U_shape at the unwrapped vertices of each particle (the copy
// used to evaluate the shape energy); interaction force moments at the minimum-image coordinates each
// contact term is evaluated with (rough pairs, and the smooth vertex-edge terms, section 9.4.2). Kinetic
// terms vanish for static packings. Sign: positive in compression; pressure P = Tr(Sigma)/2.
// Units [E/L^2]. Anchors (external constraints) are not part of the stress.
// Valid for static packings (no kinetic term) in a periodic box (InputError without one) whose side
// exceeds twice the largest particle reach (interactions.hpp); eq. (9.27) for rough interactions only.
#pragma once

#include "dpm/system/system.hpp"

#include <vector>

namespace softgrain::dpm {

Eigen::Matrix2d stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x);

// Eq. (9.27), rough interactions: stress of each particle mu,
//   Sigma_mu = (1/A_mu) [ sum_i r~_i F^shape_i
//                       - sum_i sum_{beta != mu} sum_j (h_{mu i,beta j}/r) r_{mu i,beta j} F_{mu i,beta j} ]
// with A_mu of eq. (9.21) and h the distance from vertex mu i to the contact line of the pair (eq. 9.20).
// Sum rule: sum_mu A_mu Sigma_mu = A Sigma (h_{mu i, beta j} + h_{beta j, mu i} = r).
std::vector<Eigen::Matrix2d> particle_stresses(const DpmSystem& system, const Eigen::VectorXd& x);

inline double pressure(const Eigen::Matrix2d& stress)
{
    return 0.5 * stress.trace();
}

} // namespace softgrain::dpm
