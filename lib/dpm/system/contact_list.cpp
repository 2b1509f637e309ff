#include "dpm/system/contact_list.hpp"

#include "core/errors.hpp"
#include "dpm/system/system.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace softgrain::dpm {

namespace {

// Skin of the list in units of the largest vertex diameter: a wider skin means fewer builds but more
// candidate pairs per evaluation (their number grows as (cutoff + skin)^2). 0.3 sigma_max keeps the
// candidates within 1.7 times the contacts' area while a build is needed only after vertices have moved
// 0.15 sigma, many FIRE steps near jamming. Not tuned by measurement yet.
constexpr double skin_per_sigma = 0.3;

Eigen::Vector2d vertex(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

// The lattice translation that brings a separation d to its nearest (Lees-Edwards) image, built from the
// integer image indices so that it is the same vector whatever d it came from:
// -n_y (gamma L_y, L_y) - n_x (L_x, 0).
Eigen::Vector2d image_translation(const Eigen::Vector2d& d, const Eigen::Vector2d& L, double gamma)
{
    const double ny = std::round(d.y() / L.y());
    const double nx = std::round((d.x() - ny * gamma * L.y()) / L.x());
    return {-ny * gamma * L.y() - nx * L.x(), -ny * L.y()};
}

double largest_sigma(const DpmSystem& system)
{
    double sigma = 0;
    for (const Particle& p : system.particles)
        sigma = std::max(sigma, p.sigma);
    return sigma;
}

double longest_edge(const DpmSystem& system, const Eigen::VectorXd& x)
{
    double longest = 0;
    for (const Particle& p : system.particles)
        if (p.count >= 2)
            for (int k = 0; k < p.count; ++k)
                longest = std::max(
                    longest, (vertex(x, p.first + (k + 1) % p.count) - vertex(x, p.first + k)).squaredNorm());
    return std::sqrt(longest);
}

// One image per particle pair is exact only if no particle can touch two images of another: the box side
// must exceed twice the largest pair reach 2 R + sigma, checked at every build (as the particle-level
// search checked it at every evaluation).
void require_one_image(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box) return;
    double largest_reach = 0;
    for (const Particle& p : system.particles) {
        const auto v = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
        const Eigen::Vector2d centre = v.rowwise().mean();
        const double radius = (v.colwise() - centre).colwise().norm().maxCoeff();
        largest_reach = std::max(largest_reach, 2 * radius + p.sigma);
    }
    if (2 * largest_reach >= system.box->minCoeff())
        throw NumericalError("periodic box side " + std::to_string(system.box->minCoeff()) +
                                 " below twice the largest pair reach " + std::to_string(largest_reach),
                             0, "too few particles for the box; use more particles");
}

double contact_cutoff(const DpmSystem& system, const Eigen::VectorXd& x, double skin)
{
    const double sigma = largest_sigma(system);
    if (system.interaction != InteractionKind::smooth) return sigma;
    const double edge = longest_edge(system, x) + skin;
    return std::sqrt(sigma * sigma + 0.25 * edge * edge);
}

} // namespace

ContactList::Layout ContactList::layout_of(const DpmSystem& system)
{
    Layout layout;
    for (const Particle& p : system.particles)
        layout.particles.emplace_back(p.first, p.count, p.sigma);
    layout.smooth = system.interaction == InteractionKind::smooth;
    layout.box = system.box;
    layout.strain = system.lees_edwards_strain;
    return layout;
}

ContactList::ContactList(const DpmSystem& system, const Eigen::VectorXd& x)
    : layout_(layout_of(system)),
      list_(contact_cutoff(system, x, skin_per_sigma * largest_sigma(system)),
            skin_per_sigma * largest_sigma(system), system.box, system.box ? system.lees_edwards_strain : 0.0)
{
    require_one_image(system, x);
    const int n = system.vertex_count();
    for (std::size_t m = 0; m < system.particles.size(); ++m)
        owner_.insert(owner_.end(), static_cast<std::size_t>(system.particles[m].count), static_cast<int>(m));
    built_at_ = x.head(2 * n);
    list_.build(built_at_.reshaped(2, n));
    for (const auto& [i, j] : list_.pairs()) {
        if (owner_[i] == owner_[j]) continue; // a particle's own vertices interact through its shape energy
        const Particle &a = system.particles[owner_[i]], &b = system.particles[owner_[j]];
        const Eigen::Vector2d d = vertex(x, j) - vertex(x, i);
        const Eigen::Vector2d shift = system.box
                                          ? image_translation(d, *system.box, system.lees_edwards_strain)
                                          : Eigen::Vector2d::Zero();
        pairs_.push_back({i, {j, shift, 0.5 * (a.sigma + b.sigma)}});
    }
    if (!layout_.smooth) return;
    // Each vertex's candidates from both sides (compressed rows), sorted by j.
    row_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const VertexPair& p : pairs_) {
        ++row_[p.i + 1];
        ++row_[p.neighbour.j + 1];
    }
    std::partial_sum(row_.begin(), row_.end(), row_.begin());
    neighbours_.resize(static_cast<std::size_t>(row_.back()));
    std::vector<int> fill(row_.begin(), row_.end() - 1);
    for (const VertexPair& p : pairs_) {
        neighbours_[fill[p.i]++] = p.neighbour;
        neighbours_[fill[p.neighbour.j]++] = {p.i, -p.neighbour.shift, p.neighbour.sigma};
    }
    for (int i = 0; i < n; ++i)
        std::sort(neighbours_.begin() + row_[i], neighbours_.begin() + row_[i + 1],
                  [](const VertexNeighbour& u, const VertexNeighbour& w) { return u.j < w.j; });
}

bool ContactList::same_layout(const DpmSystem& system) const
{
    if (system.particles.size() != layout_.particles.size() ||
        (system.interaction == InteractionKind::smooth) != layout_.smooth || system.box != layout_.box ||
        system.lees_edwards_strain != layout_.strain)
        return false;
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle& p = system.particles[m];
        if (layout_.particles[m] != Eigen::Vector3d(p.first, p.count, p.sigma)) return false;
    }
    return true;
}

bool ContactList::valid_for(const DpmSystem& system, const Eigen::VectorXd& x) const
{
    if (!same_layout(system)) return false;
    // A plain loop over the vertices, stopping at the first that moved too far: this test runs at every
    // force evaluation, and a reshaped expression costs an integer division per coordinate.
    const double limit = 0.25 * skin() * skin();
    const auto n = static_cast<Eigen::Index>(owner_.size());
    for (Eigen::Index v = 0; v < n; ++v)
        if ((x.segment<2>(2 * v) - built_at_.segment<2>(2 * v)).squaredNorm() > limit) return false;
    return true;
}

std::vector<VertexContact> vertex_contacts(const DpmSystem& system, const Eigen::VectorXd& x)
{
    std::vector<VertexContact> contacts;
    if (system.particles.empty()) return contacts;
    const std::shared_ptr<const ContactList> list = system.contacts.list(system, x);
    for (const VertexPair& p : list->pairs()) {
        const Eigen::Vector2d r = vertex(x, p.neighbour.j) + p.neighbour.shift - vertex(x, p.i);
        if (r.squaredNorm() < p.neighbour.sigma * p.neighbour.sigma)
            contacts.push_back({p.i, p.neighbour.j, list->particle_of(p.i), list->particle_of(p.neighbour.j),
                                r, p.neighbour.sigma});
    }
    return contacts;
}

} // namespace softgrain::dpm
