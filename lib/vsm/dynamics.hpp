// Time integration of VSM (Frenning 2022, section 5): leapfrog (core/integrators.hpp) with optional
// mass-proportional viscous damping f -= c m_a v_a for equilibrium problems (the paper's damping of [22] is
// not specified; see data/vsm/decisions.toml, damping).
#pragma once

#include "vsm/vsm_model.hpp"

#include <Eigen/Core>

#include <functional>

namespace softgrain::vsm {

struct LeapfrogState
{
    Eigen::VectorXd x; // positions, 3 per particle (column-major Points<3>)
    Eigen::VectorXd v; // velocities at t - dt/2
    double t = 0;
    long step = 0;
};

// Whether the integrator refuses a time step above the predicted stability limit (vsm/stability.hpp) before
// the first step. `off` is for stability studies only: an unstable run then ends with J <= 0 (exit 3), or,
// in the swinging cube, when its displacement leaves the energy bound of a stable run (exit 3).
enum class TimeStepCheck { refuse_above_limit, off };

class Leapfrog
{
  public:
    // Starts at positions x0 with velocities v0 at t0: v(t0 - dt/2) = v0 - dt/2 a(t0) (second-order start).
    // Throws NumericalError (step 0) when dt exceeds the predicted limit, unless check is off.
    Leapfrog(const Model& model, const Points<3>& x0, const Points<3>& v0, double dt, double damping,
             TimeStepCheck check = TimeStepCheck::refuse_above_limit, double t0 = 0);

    void step();
    const LeapfrogState& state() const { return state_; }
    Points<3> positions() const;
    // Half-step velocities v(t - dt/2). With them sum_a m_a x_a(t) x v_a(t - dt/2) is exactly conserved by
    // leapfrog when the forces exert no net torque (and sum_a m_a v_a when they have no resultant).
    Points<3> half_step_velocities() const;
    double dt() const { return dt_; }

  private:
    Eigen::VectorXd force_flat(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t);

    const Model& model_;
    LeapfrogState state_;
    Eigen::VectorXd inverse_mass_, mass_;
    double dt_, damping_;
};

// Sees the start (step 0) and every time step of a run: the model and the integrator (positions, half-step
// velocities, t, step). The scenes write ParaView frames from it (`run --vtk`); empty: not called.
using StepObserver = std::function<void(const Model&, const Leapfrog&)>;

} // namespace softgrain::vsm
