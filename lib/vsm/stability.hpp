// The explicit time-step limit of VSM (Frenning 2022, section 5: leapfrog).
//
// Leapfrog integrates the linearised system M dv/dt = -K u stably when dt < 2 / omega_max, with omega_max^2
// the largest eigenvalue of K v = omega^2 M v (K = -df/dx, M = diag(m_a), m_a = rho V_a). For a particle
// method this is a CFL condition, dt < C L / c: a 1D chain of springs (lambda + 2 mu) A / L and masses
// rho A L has omega_max = 2 c_p / L, i.e. C = 1 with c_p = sqrt((lambda + 2 mu)/rho). In VSM the contact
// (stabilisation) springs of eq. (50), K^n = xi_n E A / L and K^t = xi_t G A / L, stiffen the pairs further,
// and the Voronoi gradient couples a particle to all its neighbours. The prediction used before a run is
//   dt_limit = C_stab L_min / c_eff,   c_eff = sqrt((lambda + 2 mu + xi_n E) / rho),
// with L_min the shortest reference branch vector (ghost branches included) and C_stab measured from the
// highest frequency of the linearised model (power iteration, below) over resolutions, jitters, nu and xi:
// see verification/vsm/time_step_limit.cpp and data/vsm/decisions.toml (time-step-limit). Measured
// dt_crit c_eff / L_min on regular lattices: 0.76-0.98 with the swinging-cube walls (the same for n = 4, 6,
// 8), 1.15-1.47 with total (fixed) walls, 0.76-1.09 with free surfaces at n >= 8, falling to 0.73 (n = 4),
// 0.67 (n = 3) and 0.58 (n = 2, every particle a free corner) as nu -> 1/2; jittered layouts 1.0-2.2
// (L_min shrinks faster than the stiffness grows). C_stab = 0.55 covers every case measured.
#pragma once

#include "vsm/vsm_model.hpp"

namespace softgrain::vsm {

// The measured factor of the prediction (the smallest dt_crit c_eff / L_min found, 0.577, rounded down).
inline constexpr double stable_cfl_factor = 0.55;

// Effective wave speed of the prediction, sqrt((lambda + 2 mu + xi_n E)/rho) [m/s].
double effective_wave_speed(const Material& material, const ModelOptions& options);

// Predicted largest stable leapfrog time step C_stab L_min / c_eff [s].
double predicted_time_step_limit(const Model& model);

// Refuses a run whose time step exceeds the predicted limit: throws NumericalError (exit 3) at step 0,
// naming dt, the limit and its ingredients.
void check_time_step(const Model& model, double dt);

// Highest angular frequency omega_max [rad/s] of the model linearised about positions x at time t (elastic
// and contact forces, no viscosity), by power iteration on M^-1 K with K v from central differences of the
// forces; the Rayleigh quotient after `iterations` steps (a lower bound that converges from below).
double highest_frequency(const Model& model, const Points<3>& x, double t, int iterations = 300);

} // namespace softgrain::vsm
