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

} // namespace softgrain::sd
