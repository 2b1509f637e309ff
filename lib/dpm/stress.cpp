#include "dpm/stress.hpp"

#include "core/errors.hpp"
#include "dpm/interactions.hpp"
#include "dpm/packing_fraction.hpp"

namespace softgrain::dpm {

namespace {

// Shape part of eqs. (9.26)-(9.27) for one particle: sum_i r~_i F^shape_i^T (translation invariant, so any
// copy of the particle gives the same). `g` is a work vector of the size of x.
Eigen::Matrix2d shape_moment(const Particle& p, const Eigen::VectorXd& x, Eigen::VectorXd& g)
{
    g.segment(2 * p.first, 2 * p.count).setZero();
    shape_energy(p.shape, x, p.first, p.count, &g, nullptr);
    const auto r = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
    const auto gradient = g.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
    return -r * gradient.transpose();
}

} // namespace

Eigen::Matrix2d stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box) throw InputError("stress tensor: the system has no periodic box");
    Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    for (const Particle& p : system.particles)
        moment += shape_moment(p, x, g);
    // Interaction part: force moments at the evaluated (minimum-image) coordinates.
    if (system.interaction != InteractionKind::none)
        interaction_energy(system, x, nullptr, nullptr, all_smooth, &moment);
    return moment / system.box->prod();
}

} // namespace softgrain::dpm

namespace softgrain::dpm {

std::vector<Eigen::Matrix2d> particle_stresses(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box || system.interaction != InteractionKind::rough)
        throw InputError("per-particle stress (eq. 9.27): needs a periodic box and rough interactions");
    const std::vector<double> areas = particle_areas(system, x);
    std::vector<Eigen::Matrix2d> stresses;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle& p = system.particles[m];
        Eigen::Matrix2d moment = shape_moment(p, x, g);
        for (std::size_t b = 0; b < system.particles.size(); ++b) {
            if (b == m) continue;
            const Particle& q = system.particles[b];
            const double sigma = 0.5 * (p.sigma + q.sigma);
            const VertexSpringEnergy spring{system.kc, sigma};
            for (int i = p.first; i < p.first + p.count; ++i)
                for (int j = q.first; j < q.first + q.count; ++j) {
                    const Eigen::Vector2d ri = x.segment<2>(2 * i);
                    const Eigen::Vector2d rij = system.image(x.segment<2>(2 * j) - ri);
                    const double r = rij.norm();
                    if (r >= sigma) continue;
                    Eigen::Vector4d local;
                    local << ri, ri + rij;
                    const Eigen::Vector2d force_on_i = -local_gradient<4>(spring, local).gradient.head<2>();
                    // h: distance from vertex mu i to the contact (radical) line, eq. (9.20)'s d_mu.
                    const double h = (r * r - 0.25 * q.sigma * q.sigma + 0.25 * p.sigma * p.sigma) / (2 * r);
                    moment -= (h / r) * rij * force_on_i.transpose();
                }
        }
        stresses.push_back(moment / areas[m]);
    }
    return stresses;
}

} // namespace softgrain::dpm
