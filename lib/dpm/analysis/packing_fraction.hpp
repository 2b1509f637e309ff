// Packing fraction of rough deformable particles in a periodic box, DPM section 9.4.1, eqs. (9.18)-(9.22):
//
//   A_particles = A_polygon + A_vertices - A_sector - A_pair                                     (9.18)
//   A_polygon = sum_mu a_mu;  A_vertices = sum_mu sum_i pi sigma_mu^2/4;
//   A_sector = sum_mu sum_i sigma_mu^2 (pi - theta_mu_i)/8  (theta: turning angle; pi - theta interior);
//   A_pair = sum_mu sum_i I_{mu i, mu(i+1)} + sum_mu sum_i sum_{beta != mu} sum_j I_{mu i, beta j}  (9.19)
//   I = Theta(sigma_mb - r) [(s_mu/2)^2 acos(d/(s_mu/2)) - d sqrt((s_mu/2)^2 - d^2)],
//       d = (r^2 - (s_beta/2)^2 + (s_mu/2)^2)/(2 r)                                               (9.20)
//   phi = A_particles / (L_x L_y)                                                                      (9.22)
// I is the circular segment of vertex disk mu i beyond the radical line with disk beta j. The formula is
// exact for the union of polygons and vertex disks when no point lies in three disks and no vertex disk
// reaches a non-adjacent edge (the text's 0.1 < r_{mu i, mu j}/sigma < 1 regime); Monte-Carlo integration
// of the union (and of each term, with multiplicity) tests it.
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>
#include <vector>

namespace softgrain::dpm {

// Eq. (9.20): area of the circular segment of disk (diameter sigma_mu) beyond the radical line of the
// pair at distance r from disk (diameter sigma_beta); zero when they do not overlap.
double vertex_overlap_segment(double r, double sigma_mu, double sigma_beta);

// Each term of eq. (9.18) divided by L^2, and phi (eq. 9.22).
struct PackingAreas
{
    double polygon = 0, vertices = 0, sector = 0, pair = 0, phi = 0;
};
// With Monte-Carlo standard errors (same fields).
struct PackingAreasEstimate
{
    PackingAreas value, error;
};

// The terms of eq. (9.21) for every particle (areas in L^2, not divided by the box; phi holds A_mu itself).
std::vector<PackingAreas> particle_area_terms(const DpmSystem& system, const Eigen::VectorXd& x);
// A_mu of every particle, eq. (9.21).
std::vector<double> particle_areas(const DpmSystem& system, const Eigen::VectorXd& x);

// Analytic eqs. (9.18)-(9.22) for the periodic system (system.box must be set).
PackingAreas packing_areas_analytic(const DpmSystem& system, const Eigen::VectorXd& x);

// Monte-Carlo integration with `samples` uniform points in the box: phi = fraction in the union;
// A_polygon = fraction in some polygon; A_vertices = mean number of vertex disks covering a point;
// A_sector = mean number of disks covering a point inside their own polygon; A_pair = the multiplicity
// excess [polygon] + #disks - #sectors - [union] (the area eq. 9.18 subtracts). Errors: sample standard
// deviation over sqrt(samples).
PackingAreasEstimate packing_areas_monte_carlo(const DpmSystem& system, const Eigen::VectorXd& x,
                                               long samples, std::uint64_t seed);

} // namespace softgrain::dpm
