// The time-step limits of the SPD shell model (Trivino et al., section 2.4): the critical time step
// dt_c = sqrt(m/k_max) that the scenes' dt_factor scales, and the stability limit of velocity Verlet with the
// damped contacts, which a run's dt is checked against before it starts.
#pragma once

#include "spd/shell_model.hpp"

namespace softgrain::spd {

// SPD section 2.4: dt_c = sqrt(m / k_max), m the smallest free vertex mass and k_max the largest of k_s, the
// bending stiffness 4 k_b / l^2 seen by a vertex, the contact stiffness k_n, the link stiffnesses and the
// core stiffness K_Omega s^2 sum_k |dA/dx_k|^2 / V0 (the eigenvalue of the rank-one core Hessian, decision
// spd-dtc-kmax) [s].
double critical_time_step(const ShellModel& model);

// Largest stable time step of the scheme (decision spd-stability-limit): min(dt_c, the limit of the damped
// normal contact). The contact damping c_n enters with the half-step velocity, so a vertex on a wall is the
// damped oscillator v' = v - h (omega^2 x + gamma v), x' = x + h v' (omega^2 = k_n/m, gamma = c_n/m), stable
// iff h^2 omega^2 + 2 h gamma < 4:
//   h < (sqrt(gamma^2 + 4 omega^2) - gamma)/omega^2,
// i.e. 2 (sqrt(2) - 1) sqrt(m/k_n) = 0.83 sqrt(m/k_n) for the critical c_n = 2 sqrt(m k_n). Two free shells
// can touch vertex to vertex: each vertex then lies within reach of the other's element end, so the contact
// is counted both ways, and the relative motion of the two vertices (reduced mass m/2) sees 2 k_n and
// 2 c_n: omega^2 = 4 k_n/m, gamma = 4 c_n/m, the limit (sqrt(5) - 2) sqrt(m/k_n) = 0.236 sqrt(m/k_n) for
// the critical c_n (decision spd-vertex-pair-stability). Above it the pair flips at every step, a limit
// cycle that the one-sided normal force keeps bounded [s].
double stable_time_step(const ShellModel& model);

// Refuses a run whose time step is above stable_time_step: throws NumericalError (exit 3) naming dt, the
// limit and dt_c; InputError (exit 2) for dt <= 0.
void check_time_step(const ShellModel& model, double dt);

} // namespace softgrain::spd
