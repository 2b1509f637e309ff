// Soft Dynamics of several contacting particles (Rognon & Gay, note [20]).
//
// Each bonded pair ij has a centre vector X_ij = X_j - X_i, unit normal n_ij, distance
// |X_ij| = 2R + h_ij - 2 delta_ij (eq. 2), and its own zeta_ij, C_ij, D_ij (eqs. 4, 8, 9). The pair force
// F_ij = F_ela(a_ij, delta_ij) (> 0 when repulsive) balances the external forces, F_i^ext = sum_j F_ij n_ij
// (eq. 1 per particle, a vector sum). Differentiating this balance with eq. (8) per pair (the normals n_ij
// held fixed: normal motion only, as in the paper) gives one vector equation per particle for the centre
// velocities V_i:
//   sum_j C_ij n_ij n_ij . (V_j - V_i) = -dF_i^ext/dt - sum_j (C_ij/D_ij)(F_ij - F_adh_ij) n_ij.
// (The paper prints "+" before the last sum; deriving it from eq. 9 gives "-", the sign for which two
// particles reproduce the pair result: see data/sd/decisions.toml, sd-note20-sign.) The equations are not
// independent (uniform translation, and rigid rotation in 2D, are free): the d rows of particle 0 are
// replaced by zero mean velocity, as the paper suggests, and in 2D one row of zero mean rotation is added;
// the system is solved with Eigen's complete orthogonal decomposition. Each gap then follows eq. (7):
// h-dot_ij = -(F_ij - F_adh_ij)/zeta_ij.
#pragma once

#include "sd/approach.hpp"
#include "sd/contact_laws.hpp"

#include <functional>
#include <utility>
#include <vector>

namespace softgrain::sd {

struct ManyParticleSystem
{
    Material material;
    ContactLaws laws;
    int dimension = 1;                      // 1 (a line) or 2
    std::vector<std::pair<int, int>> bonds; // interacting pairs (i, j)
    // External force on each particle and its time derivative, flat arrays of dimension * N (N, N/s).
    std::function<void(double t, std::vector<double>& force, std::vector<double>& rate)> external;
};

struct ManyParticleRates
{
    std::vector<double> velocity;   // V_i, flat dimension * N (m/s)
    std::vector<double> gap_rate;   // h-dot per bond (m/s)
    std::vector<double> pair_force; // F_ij = F_ela per bond (N)
    std::vector<double> deflection; // delta_ij per bond (m)
    double residual = 0; // max |row residual| of the full (unreplaced) system, relative to its scale
};

// positions: flat dimension * N (m); gaps: one per bond (m), all > 0.
ManyParticleRates many_particle_rates(const ManyParticleSystem& system, double t,
                                      const std::vector<double>& positions, const std::vector<double>& gaps);

struct ManySample
{
    double t;
    std::vector<double> positions, gaps;
    ManyParticleRates rates;
};

// Integrates (positions, gaps) with GSL's rk8pd (absolute error tol * delta_scale per component, relative
// tol), sampling at t = 0 and at each of output_times (increasing), until the smallest gap falls below h_min.
std::vector<ManySample> integrate_many(const ManyParticleSystem& system, std::vector<double> positions,
                                       std::vector<double> gaps, const std::vector<double>& output_times,
                                       double h_min, double tolerance, double delta_scale, long& steps);

// A system at rest in its balanced configuration, every gap h0: centre distances 2R + h0 - 2 delta0 (eq. 2),
// delta0 balancing the force every bond carries at h0 (eq. 1).
struct BalancedStart
{
    ManyParticleSystem system;
    std::vector<double> positions; // flat dimension * N (m)
    double pair_force = 0;         // the force every bond carries (N)
    double deflection = 0;         // delta0 (m)
    double distance = 0;           // |X_ij| (m)
};

// A line of `particles` bonded neighbours compressed at its ends by `force`: every bond carries `force`.
BalancedStart compressed_line(const Material& material, int particles, double force, double h0);

// An equilateral triangle of three particles, each pushed towards the centre by `force` (a fixed direction):
// every bond carries force / sqrt 3 (two bonds at 30 degrees from the inward radius of each particle).
BalancedStart pushed_triangle(const Material& material, double force, double h0);

// How far a run stays from what note [20] and the pair dynamics predict, as maxima over its samples.
struct ManyMaxima
{
    double mean_velocity = 0;      // |mean_i V_i| / max_i |V_i| per component: the mean velocity stays zero
    double symmetry_deviation = 0; // (h_max - h_min) / h_min over the bonds: the load is shared alike
    // |h-dot| |t - t_ref(h)| / h per bond: the relative error of h(t) against the pair reference, the same
    // bond alone under the force it carries, t_ref by quadrature (eq. 7 with eq. 1).
    double pair_reference_error = 0;
    double pair_force_residual = 0;    // |F_ij / pair_force - 1|: the bonds carry the statics' force
    double linear_system_residual = 0; // ManyParticleRates::residual
};
// `pair`: the bond alone from h0 under constant loading by pair_force.
ManyMaxima many_maxima(const std::vector<ManySample>& samples, int dimension, const ApproachProblem& pair,
                       double pair_force);

} // namespace softgrain::sd
