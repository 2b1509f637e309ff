#include "dpm/system/vertex_pairs3d.hpp"

#include "core/errors.hpp"
#include "dpm/system/system3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace softgrain::dpm {

namespace {

// Skin in units of the largest vertex diameter, as in 2D (contact_list.cpp): a build is needed only after
// a vertex has moved 0.15 sigma, while the candidates stay within 1.3^3 = 2.2 times the pairs within reach.
constexpr double skin_per_sigma = 0.3;

// gamma and gamma - 1 give the same images of the cube: the one in [-1/2, 1/2].
double wrapped_strain(const DpmSystem3d& system)
{
    return system.lees_edwards_strain - std::round(system.lees_edwards_strain);
}

double largest_sigma(const DpmSystem3d& system)
{
    double sigma = 0;
    for (const Particle3d& p : system.particles)
        sigma = std::max(sigma, p.sigma);
    return sigma;
}

// The coordinates with the shear undone, u = (x - gamma y, y, z), 3 x vertices.
Eigen::Matrix3Xd unsheared(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    Eigen::Matrix3Xd u = x.head(3 * system.vertex_count()).reshaped(3, system.vertex_count());
    const double gamma = wrapped_strain(system);
    if (gamma != 0) u.row(0) -= gamma * u.row(1);
    return u;
}

} // namespace

VertexPairList3d::VertexPairList3d(const DpmSystem3d& system, const Eigen::VectorXd& x)
    : box_(system.box), strain_(system.lees_edwards_strain), skin_(skin_per_sigma * largest_sigma(system))
{
    const double reach = largest_sigma(system) * (1 + std::abs(wrapped_strain(system)));
    if (system.box && *system.box <= 2 * reach)
        throw NumericalError(
            "periodic box side " + std::to_string(*system.box) + " not above twice the vertex diameter " +
                std::to_string(largest_sigma(system)) + " times 1 + |Lees-Edwards strain|",
            0, "the packing is compressed beyond the minimum-image range; lower the pressure");
    std::vector<int> owner;
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle3d& p = system.particles[m];
        particles_.emplace_back(p.first, p.count, p.sigma);
        owner.insert(owner.end(), static_cast<std::size_t>(p.count), static_cast<int>(m));
    }
    std::optional<Vec<3>> periodic;
    if (system.box) periodic = Vec<3>::Constant(*system.box);
    NeighbourList<3> list(reach, skin_, periodic);
    built_at_ = unsheared(system, x);
    list.build(built_at_);
    for (const auto& [i, j] : list.pairs()) {
        if (owner[i] == owner[j]) continue; // a particle's own vertices interact through its shape energy
        pairs_.push_back({i, j, 0.5 * (system.particles[owner[i]].sigma + system.particles[owner[j]].sigma)});
    }
}

bool VertexPairList3d::same_layout(const DpmSystem3d& system) const
{
    if (system.particles.size() != particles_.size() || system.box != box_ ||
        system.lees_edwards_strain != strain_)
        return false;
    for (std::size_t m = 0; m < particles_.size(); ++m) {
        const Particle3d& p = system.particles[m];
        if (particles_[m] != Eigen::Vector3d(p.first, p.count, p.sigma)) return false;
    }
    return true;
}

bool VertexPairList3d::valid_for(const DpmSystem3d& system, const Eigen::VectorXd& x) const
{
    if (!same_layout(system)) return false;
    const double gamma = wrapped_strain(system), limit = 0.25 * skin_ * skin_;
    for (Eigen::Index v = 0; v < built_at_.cols(); ++v) {
        Eigen::Vector3d u = x.segment<3>(3 * v);
        u.x() -= gamma * u.y();
        if ((u - built_at_.col(v)).squaredNorm() > limit) return false;
    }
    return true;
}

} // namespace softgrain::dpm
