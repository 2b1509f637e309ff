#include "dpm/relax/rigid.hpp"

#include "dpm/analysis/stress.hpp"

#include <cmath>

namespace softgrain::dpm {

namespace {

// Vertices of particle p as a 2 x n block of x.
auto vertices(const Particle& p, Eigen::VectorXd& x)
{
    return x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
}

} // namespace

FireResult relax_rigid_fire(const DpmSystem& system, Eigen::VectorXd& x, const FireOptions& options)
{
    const auto& particles = system.particles;
    const std::size_t n = particles.size();
    std::vector<Eigen::Matrix2Xd> offsets(n); // reference shape about the centre
    std::vector<double> radius(n);
    Eigen::VectorXd q(3 * n);
    for (std::size_t m = 0; m < n; ++m) {
        const auto v = vertices(particles[m], x);
        const Eigen::Vector2d c = v.rowwise().mean();
        offsets[m] = v.colwise() - c;
        radius[m] = std::max(offsets[m].colwise().norm().maxCoeff(), 1e-300);
        q.segment<3>(3 * m) << c, 0.0;
    }
    const auto place = [&](const Eigen::VectorXd& coordinates, Eigen::VectorXd& y) {
        for (std::size_t m = 0; m < n; ++m) {
            const double theta = coordinates(3 * m + 2) / radius[m];
            const Eigen::Matrix2d rotation{{std::cos(theta), -std::sin(theta)},
                                           {std::sin(theta), std::cos(theta)}};
            vertices(particles[m], y) = (rotation * offsets[m]).colwise() + coordinates.segment<2>(3 * m);
        }
    };
    Eigen::VectorXd y = x, g(x.size());
    const FireResult result = fire_minimise(
        q,
        [&](const Eigen::VectorXd& coordinates, Eigen::VectorXd& force) {
            place(coordinates, y);
            g.setZero();
            const double energy = total_energy(system, y, &g, nullptr);
            force.resize(coordinates.size());
            for (std::size_t m = 0; m < n; ++m) {
                const Particle& p = particles[m];
                const auto r = vertices(p, y);
                const auto f = g.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
                const Eigen::Vector2d c = coordinates.segment<2>(3 * m);
                double torque = 0;
                for (int i = 0; i < p.count; ++i)
                    torque -= (r(0, i) - c.x()) * f(1, i) - (r(1, i) - c.y()) * f(0, i);
                force.segment<3>(3 * m) << -f.rowwise().sum(), torque / radius[m];
            }
            return energy;
        },
        options);
    place(q, x);
    return result;
}

Eigen::Matrix2d rigid_stress_tensor(const DpmSystem& system, const Eigen::VectorXd& x)
{
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    total_energy(system, x, &g, nullptr, interaction_part);
    Eigen::Matrix2d constraint_moment = Eigen::Matrix2d::Zero();
    for (const Particle& p : system.particles) {
        const auto r = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const auto gradient = g.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        // sum_i r~_i F_i^T with the constraint force F_i = -f_i = +dU/dr_i.
        constraint_moment += (r.colwise() - r.rowwise().mean()) * gradient.transpose();
    }
    return stress_tensor(system, x) + constraint_moment / system.box->prod();
}

} // namespace softgrain::dpm
