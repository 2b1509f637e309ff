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

double largest_sigma(const DpmSystem3d& system)
{
    double sigma = 0;
    for (const Particle3d& p : system.particles)
        sigma = std::max(sigma, p.sigma);
    return sigma;
}

double longest_edge(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    double longest = 0;
    for (const Particle3d& p : system.particles)
        for (const MeshEdge& e : system.meshes[p.mesh].edges)
            longest = std::max(
                longest,
                (x.segment<3>(3 * (p.first + e.b)) - x.segment<3>(3 * (p.first + e.a))).squaredNorm());
    return std::sqrt(longest);
}

// The contact range c of the interaction in space (header).
double range_of_contacts(const DpmSystem3d& system, const Eigen::VectorXd& x, double skin)
{
    const double range = largest_sigma(system);
    if (system.interaction != InteractionKind::smooth) return range;
    return range +
           (longest_edge(system, x) + (1 + std::abs(wrapped_strain3d(system))) * skin) / std::sqrt(3.0);
}

// The coordinates with the shear undone, u = (x - gamma y, y, z), 3 x vertices.
Eigen::Matrix3Xd unsheared(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    Eigen::Matrix3Xd u = x.head(3 * system.vertex_count()).reshaped(3, system.vertex_count());
    const double gamma = wrapped_strain3d(system);
    if (gamma != 0) u.row(0) -= gamma * u.row(1);
    return u;
}

} // namespace

double wrapped_strain3d(const DpmSystem3d& system)
{
    return system.lees_edwards_strain - std::round(system.lees_edwards_strain);
}

VertexPairList3d::VertexPairList3d(const DpmSystem3d& system, const Eigen::VectorXd& x)
    : box_(system.box), strain_(system.lees_edwards_strain),
      smooth_(system.interaction == InteractionKind::smooth), skin_(skin_per_sigma * largest_sigma(system)),
      range_(range_of_contacts(system, x, skin_))
{
    const double reach = range_ * (1 + std::abs(wrapped_strain3d(system)));
    one_image_ = !system.box || *system.box > 2 * reach;
    if (system.box && *system.box <= (smooth_ ? 1 : 2) * reach)
        throw NumericalError("periodic box side " + std::to_string(*system.box) + " not above " +
                                 (smooth_ ? "" : "twice ") + "the contact reach " + std::to_string(reach) +
                                 " (vertex diameter, for smooth contacts plus the longest edge over sqrt 3, "
                                 "times 1 + |Lees-Edwards strain|)",
                             0, "the packing is compressed beyond the image range; lower the pressure");
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle3d& p = system.particles[m];
        particles_.emplace_back(p.first, p.count, p.sigma);
        owner_.insert(owner_.end(), static_cast<std::size_t>(p.count), static_cast<int>(m));
    }
    std::optional<Vec<3>> periodic;
    if (system.box) periodic = Vec<3>::Constant(*system.box);
    NeighbourList<3> list(reach, skin_, periodic);
    built_at_ = unsheared(system, x);
    list.build(built_at_);
    for (const auto& [i, j] : list.pairs()) {
        if (owner_[i] == owner_[j]) continue; // a particle's own vertices interact through its shape energy
        pairs_.push_back(
            {i, j, 0.5 * (system.particles[owner_[i]].sigma + system.particles[owner_[j]].sigma)});
    }
}

bool VertexPairList3d::same_layout(const DpmSystem3d& system) const
{
    if (system.particles.size() != particles_.size() || system.box != box_ ||
        system.lees_edwards_strain != strain_ || (system.interaction == InteractionKind::smooth) != smooth_)
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
    const double gamma = wrapped_strain3d(system), limit = 0.25 * skin_ * skin_;
    for (Eigen::Index v = 0; v < built_at_.cols(); ++v) {
        Eigen::Vector3d u = x.segment<3>(3 * v);
        u.x() -= gamma * u.y();
        if ((u - built_at_.col(v)).squaredNorm() > limit) return false;
    }
    return true;
}

} // namespace softgrain::dpm
