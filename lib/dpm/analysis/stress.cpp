#include "dpm/analysis/stress.hpp"

#include "core/errors.hpp"
#include "dpm/analysis/packing_fraction.hpp"
#include "dpm/laws/interactions.hpp"

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
    std::vector<Eigen::Matrix2d> moments;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    for (const Particle& p : system.particles)
        moments.push_back(shape_moment(p, x, g));
    for (const VertexContact& c : vertex_contacts(system, x)) {
        const double sigma_a = system.particles[c.a].sigma, sigma_b = system.particles[c.b].sigma;
        Eigen::Vector4d local;
        local << Eigen::Vector2d::Zero(), c.r;
        const Eigen::Vector2d force_on_i =
            -local_gradient<4>(VertexSpringEnergy{system.kc, c.sigma}, local).gradient.head<2>();
        const double r = c.r.norm();
        // h: distance from the vertex to the contact (radical) line, eq. (9.20)'s d_mu, seen from either side;
        // r_ji F_j^T = r_ij F_i^T (both reversed).
        const double h_i = (r * r - 0.25 * sigma_b * sigma_b + 0.25 * sigma_a * sigma_a) / (2 * r);
        const double h_j = (r * r - 0.25 * sigma_a * sigma_a + 0.25 * sigma_b * sigma_b) / (2 * r);
        const Eigen::Matrix2d moment = c.r * force_on_i.transpose() / r;
        moments[c.a] -= h_i * moment;
        moments[c.b] -= h_j * moment;
    }
    std::vector<Eigen::Matrix2d> stresses;
    for (std::size_t m = 0; m < moments.size(); ++m)
        stresses.push_back(moments[m] / areas[m]);
    return stresses;
}

} // namespace softgrain::dpm
