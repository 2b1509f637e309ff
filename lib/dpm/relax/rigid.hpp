// Rough disks of DPM section 9.4.2 (Fig. 9.13a, c): regular polygons whose vertices "move together as a
// rigid body", interacting by the rough vertex-vertex potential eqs. (9.3)-(9.4); no shape energy.
//
// Generalised coordinates per particle: centre c (vertex mean) and R_mu theta (rotation times the
// circumradius, so that all coordinates are lengths); vertices r_i = c + Rot(theta) (r_i0 - c0).
// Generalised forces: sum_i f_i and torque / R_mu, with f_i = -dU/dr_i. Stress of the rigid packing:
// eq. (9.26) with the rigid-body constraint forces -f_i in place of F^shape (at equilibrium they balance
// the contact forces on every vertex), i.e. the branch-vector virial. Units as the rest of lib/dpm.
#pragma once

#include "core/fire.hpp"
#include "dpm/system/system.hpp"

namespace softgrain::dpm {

// FIRE on the rigid-body coordinates of every particle (the current shapes are kept exactly).
FireResult relax_rigid_fire(const DpmSystem& system, Eigen::VectorXd& x, const FireOptions& options);

// Stress tensor of a static packing of rigid particles: eq. (9.26) with F^shape_i = -f_i (see above).
Eigen::Matrix2d rigid_stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
