// Explicit time integrators on flat state vectors (one entry per degree of freedom).
//
// `inverse_mass` holds 1/m per degree of freedom. `compute_force(x, v, f)` overwrites f with the force
// at positions x (velocities v are passed for velocity-dependent forces such as viscous damping; in
// velocity Verlet they are the half-step velocities, so a damping force makes the scheme first order in dt).
#pragma once

#include <Eigen/Core>

namespace softgrain {

// Velocity Verlet (kick-drift-kick), second order, symplectic. For a linear spring of angular frequency
// omega it is stable for dt < 2/omega. On entry f holds the force at x; on return x, v, f are at t + dt.
template <class ForceFn>
void velocity_verlet_step(Eigen::VectorXd& x, Eigen::VectorXd& v, Eigen::VectorXd& f,
                          const Eigen::VectorXd& inverse_mass, double dt, ForceFn&& compute_force)
{
    v.array() += 0.5 * dt * inverse_mass.array() * f.array();
    x += dt * v;
    compute_force(x, v, f);
    v.array() += 0.5 * dt * inverse_mass.array() * f.array();
}

// Leapfrog: v holds v(t - dt/2) on entry, v(t + dt/2) on return; x goes from t to t + dt.
// compute_force(x, v, f) is evaluated at x(t).
template <class ForceFn>
void leapfrog_step(Eigen::VectorXd& x, Eigen::VectorXd& v, Eigen::VectorXd& f,
                   const Eigen::VectorXd& inverse_mass, double dt, ForceFn&& compute_force)
{
    compute_force(x, v, f);
    v.array() += dt * inverse_mass.array() * f.array();
    x += dt * v;
}

// Viscous (velocity-proportional) damping, f -= c v, with c in [force / velocity].
inline void add_viscous_damping(Eigen::VectorXd& f, const Eigen::VectorXd& v, double coefficient)
{
    f -= coefficient * v;
}

} // namespace softgrain
