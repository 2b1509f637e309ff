// Simple-shear test of two deformable particles and their effective friction coefficient, DPM section
// 9.3.3 (Figs. 9.8, 9.9) and eqs. (9.10)-(9.13).
//
// Two N-gons of circumradius R = C sigma (sigma = vertex diameter = 1, k_c = 1). Particle beta has a flat
// bottom edge whose two vertices ("1, 2" of the paper) are held by springs k_constraint |r - r0|^2/2;
// particle mu points a vertex down and its three top vertices ("1, 2, 3", decision dpm-shear-mu-vertices)
// are held by springs whose rest positions move right by dx = 0.016 D_beta per step,
// D_beta = max_ij |x . r_{beta i, beta j}| + sigma. After each shift the total energy is minimised (FIRE,
// decision dpm-shear-fire) and
//   mu_eff = F_t / F_n,  F_n = F_mb . n_bm,  F_t = F_mb . t_bm,  n_bm x t_bm = z          (9.10)-(9.12)
// with F_mb = -sum_i grad_{r_mu i} U_int the force of beta on mu and n_bm the unit vector from beta's to
// mu's centre of mass (vertex mean). The vertical separation of the anchors is fixed by the rest overlap
// `overlap` = 1 - r/sigma of mu's bottom vertex with beta's two top vertices in the groove position of the
// undeformed polygons (decision dpm-shear-overlap), applied to the relaxed rest shapes (decision
// dpm-shear-rest-shapes: floppy particles with A0 > A_min are not regular polygons).
#pragma once

#include "dpm/system/system.hpp"

#include <functional>
#include <vector>

namespace softgrain::dpm {

struct ShearTestOptions
{
    InteractionKind interaction = InteractionKind::rough;
    int nodes = 8;
    double C = 1.3;                     // R / sigma
    std::optional<double> A0;           // preferred shape parameter >= A_min(nodes); absent: A_min
    double kl = 100;                    // k_l / k_c
    double kb = 171;                    // k_b / (k_c sigma^2)
    double ka = 14;                     // k_a a0^2 / (k_c sigma^2)
    double k_constraint = 100;          // k_constraint / k_c
    double overlap = 0.01;              // rest overlap in the groove position, fraction of sigma
    double dx = 0.016;                  // shift per step, fraction of D_beta
    double x_start = -0.7, x_end = 0.7; // range of x_bm / D_beta
    std::uint64_t seed = 1; // noise (1e-3 l0) on floppy particles (k_b = 0) to leave symmetric saddles
};

struct ShearSample
{
    double x_over_d = 0; // x_bm / D_beta
    double mu_eff = 0;
    double normal_force = 0, tangential_force = 0; // F_n, F_t [k_c sigma]
    double energy = 0;
    long iterations = 0;
};

struct ShearTestResult
{
    std::vector<ShearSample> samples; // only configurations in contact (F_n > 0)
    double mu_eff_max = 0;            // max over the samples
    double x_at_max = 0;              // x_bm / D_beta where it occurs
    double d_beta = 0;                // D_beta [sigma]
    long iterations = 0;              // FIRE iterations in all
    DpmSystem system;                 // final state
    Eigen::VectorXd x;
    Eigen::VectorXd x_star; // the configuration at the maximum of mu_eff (the star of Fig. 9.8d)
    // Every relaxed configuration (in contact or not) with its x_bm / D_beta, for the frames of
    // Figs. 9.8, 9.9.
    std::vector<std::pair<double, Eigen::VectorXd>> configurations;
};

// Force of beta (particle 0) on mu (particle 1), F_mb = -sum_i grad_{r_mu i} U_int, projected on n_bm (from
// beta's to mu's vertex mean) and t_bm (n x t = z), eqs. (9.11)-(9.12); mu_eff = tangential / normal (9.10).
struct ContactForce
{
    double normal = 0, tangential = 0; // [k_c sigma]
    double energy = 0;                 // U_int [k_c sigma^2]
};
ContactForce contact_force_on_mu(const DpmSystem& system, const Eigen::VectorXd& x);

// Eq. (9.13): maximum friction of rough circular particles, ([1/(C sin(pi/N))]^2 - 1)^(-1/2).
double rough_friction_maximum(double C, int nodes);

// Called after each relaxed shear step with the system (its anchors where that step put them), the relaxed
// coordinates and the step's sample (mu_eff is 0 where F_n <= 0: not in contact, no row of shear.dat).
using ShearStepObserver =
    std::function<void(const DpmSystem& system, const Eigen::VectorXd& x, const ShearSample& sample)>;

ShearTestResult simple_shear_test(const ShearTestOptions& options, const ShearStepObserver& observe = {});

} // namespace softgrain::dpm
