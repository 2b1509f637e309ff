#include "dpm/stress.hpp"

#include "core/errors.hpp"
#include "dpm/interactions.hpp"

namespace softgrain::dpm {

Eigen::Matrix2d stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box) throw InputError("stress tensor: the system has no periodic box");
    Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
    // Shape part of eq. (9.26): r~ F^shape per particle (translation invariant, so any copy gives the same).
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    for (const Particle& p : system.particles) {
        g.segment(2 * p.first, 2 * p.count).setZero();
        shape_energy(p.shape, x, p.first, p.count, &g, nullptr);
        const auto r = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const auto force = g.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        moment -= r * force.transpose();
    }
    // Interaction part: force moments at the evaluated (minimum-image) coordinates.
    if (system.interaction != InteractionKind::none)
        interaction_energy(system, x, nullptr, nullptr, all_smooth, &moment);
    return moment / system.box->prod();
}

} // namespace softgrain::dpm
