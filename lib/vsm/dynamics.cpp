#include "vsm/dynamics.hpp"

#include "core/errors.hpp"
#include "core/integrators.hpp"
#include "vsm/stability.hpp"

#include <cmath>

namespace softgrain::vsm {

namespace {
Eigen::VectorXd flatten(const Points<3>& p)
{
    return Eigen::Map<const Eigen::VectorXd>(p.data(), p.size());
}
Points<3> unflatten(const Eigen::VectorXd& v)
{
    return Eigen::Map<const Points<3>>(v.data(), 3, v.size() / 3);
}
} // namespace

Leapfrog::Leapfrog(const Model& model, const Points<3>& x0, const Points<3>& v0, double dt, double damping,
                   TimeStepCheck check, double t0)
    : model_(model), dt_(dt), damping_(damping)
{
    if (check == TimeStepCheck::refuse_above_limit) check_time_step(model, dt);
    const auto n = static_cast<Eigen::Index>(model.size());
    mass_.resize(3 * n);
    for (Eigen::Index a = 0; a < n; ++a)
        mass_.segment<3>(3 * a).setConstant(model.mass()[static_cast<std::size_t>(a)]);
    inverse_mass_ = mass_.cwiseInverse();
    state_.x = flatten(x0);
    state_.t = t0;
    const Eigen::VectorXd v_start = flatten(v0);
    const Eigen::VectorXd f0 = force_flat(state_.x, v_start, t0);
    state_.v = v_start - 0.5 * dt_ * inverse_mass_.cwiseProduct(f0);
}

Eigen::VectorXd Leapfrog::force_flat(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double t)
{
    const Points<3> velocities = unflatten(v);
    Eigen::VectorXd f = flatten(model_.forces(unflatten(x), t, state_.step, &velocities));
    if (!f.allFinite())
        throw NumericalError("non-finite force", state_.step,
                             "time step above the stability limit (see vsm/stability.hpp)");
    if (damping_ > 0) f.array() -= damping_ * mass_.array() * v.array(); // mass-proportional damping
    return f;
}

void Leapfrog::step()
{
    Eigen::VectorXd f(state_.x.size());
    leapfrog_step(state_.x, state_.v, f, inverse_mass_, dt_,
                  [&](const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& out) {
                      out = force_flat(x, v, state_.t);
                  });
    state_.t += dt_;
    ++state_.step;
}

Points<3> Leapfrog::positions() const
{
    return unflatten(state_.x);
}

Points<3> Leapfrog::half_step_velocities() const
{
    return unflatten(state_.v);
}

} // namespace softgrain::vsm
