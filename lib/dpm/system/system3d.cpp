#include "dpm/system/system3d.hpp"

#include "core/errors.hpp"
#include "core/neighbour_list.hpp"
#include "dpm/laws/interactions.hpp"
#include "dpm/laws/interactions3d.hpp"
#include "dpm/system/particle_sum.hpp"
#include "dpm/system/scale_packing.hpp"
#include "dpm/system/system.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace softgrain::dpm {

Eigen::Vector3d DpmSystem3d::image(const Eigen::Vector3d& d) const
{
    return box ? lees_edwards_image<3>(d, Eigen::Vector3d::Constant(*box), lees_edwards_strain) : d;
}

void DpmSystem3d::add_particle(int mesh, const Eigen::Matrix3Xd& v, double sigma,
                               const ShapeParameters3d& shape, Eigen::VectorXd& x)
{
    if (mesh < 0 || mesh >= static_cast<int>(meshes.size()) || v.cols() != meshes[mesh].vertex_count())
        throw std::logic_error("DpmSystem3d::add_particle: vertices do not match the mesh");
    Particle3d p;
    p.first = vertex_count();
    p.mesh = mesh;
    p.count = static_cast<int>(v.cols());
    p.sigma = sigma;
    p.shape = shape;
    particles.push_back(p);
    x.conservativeResize(3 * vertex_count());
    x.segment(3 * p.first, 3 * p.count) = v.reshaped();
}

Eigen::Matrix3Xd DpmSystem3d::vertices(const Particle3d& p, const Eigen::VectorXd& x) const
{
    return x.segment(3 * p.first, 3 * p.count).reshaped(3, p.count);
}

namespace {

// Vertices from which the shape energies are summed in parallel over particles (particle_sum.hpp). FIRE on
// 2 threads against 1 (dpm.bench dimension = 3, shells): 1.45x faster at 8 icosahedra (96 vertices), 1.8x
// at 8 x 42 (336); below some 64 vertices the threads' start-up would cost more than they share.
constexpr int parallel_shape_vertices3d = 64;

// Calls contact(i, j, sigma_mb, r_ij) for every vertex pair of different particles closer than sigma_mb
// (r_ij = minimum image of r_j - r_i), in (i, j) order, from the system's Verlet list (vertex_pairs3d.hpp).
template <class Contact>
void for_each_contact(const DpmSystem3d& s, const Eigen::VectorXd& x, const Contact& contact)
{
    if (s.particles.size() < 2 || s.kc == 0) return;
    const std::shared_ptr<const VertexPairList3d> list = s.contacts.list(s, x);
    for (const CandidatePair3d& pair : list->pairs()) {
        const Eigen::Vector3d rij = s.image(x.segment<3>(3 * pair.j) - x.segment<3>(3 * pair.i));
        if (rij.squaredNorm() < pair.sigma * pair.sigma)
            contact(pair.i, pair.j, pair.sigma, rij); // Theta(sigma_mb - r), eq. (9.4)
    }
}

} // namespace

double interaction_energy3d(const DpmSystem3d& s, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                            HessianSink hessian, Eigen::Matrix3d* virial)
{
    if (s.interaction == InteractionKind::none) return 0;
    if (s.interaction == InteractionKind::smooth)
        return smooth_interaction_energy3d(s, x, gradient, hessian, virial);
    double energy = 0;
    for_each_contact(s, x, [&](int i, int j, double sigma, const Eigen::Vector3d& rij) {
        const std::array<int, 2> pair{i, j};
        Eigen::Matrix<double, 6, 1> local;
        local << x.segment<3>(3 * i), x.segment<3>(3 * i) + rij; // j at its image nearest to i
        energy += add_local_term<3, 2>(VertexSpring<3>{s.kc, sigma}, pair, local, gradient, hessian, virial);
    });
    return energy;
}

std::vector<int> contact_counts3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    if (s.interaction == InteractionKind::smooth) return smooth_contact_counts3d(s, x);
    std::vector<int> owner(s.vertex_count());
    for (std::size_t m = 0; m < s.particles.size(); ++m)
        std::fill(owner.begin() + s.particles[m].first,
                  owner.begin() + s.particles[m].first + s.particles[m].count, static_cast<int>(m));
    std::vector<int> counts(s.particles.size(), 0);
    for_each_contact(s, x, [&](int i, int j, double, const Eigen::Vector3d&) {
        ++counts[owner[i]];
        ++counts[owner[j]];
    });
    return counts;
}

std::vector<std::pair<int, int>> touching_pairs3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    if (s.interaction == InteractionKind::smooth) return smooth_touching_pairs3d(s, x);
    std::vector<std::pair<int, int>> pairs;
    if (s.interaction == InteractionKind::none) return pairs;
    for_each_contact(s, x, [&](int i, int j, double, const Eigen::Vector3d&) { pairs.emplace_back(i, j); });
    return pairs;
}

double total_energy3d(const DpmSystem3d& s, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                      HessianSink hessian)
{
    // Parallel on the gradient path only (the Hessian sinks are shared by all particles).
    const bool parallel = !hessian && s.vertex_count() >= parallel_shape_vertices3d;
    const double energy = sum_over_particles(s.particles.size(), parallel, [&](std::size_t m) {
        const Particle3d& p = s.particles[m];
        return shape_energy3d(p.shape, s.meshes[p.mesh], x, p.first, gradient, hessian);
    });
    return energy + interaction_energy3d(s, x, gradient, hessian);
}

Eigen::Matrix3d stress_tensor3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    if (!s.box) throw InputError("stress tensor: the system has no periodic box");
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    // Shape part: sum_i r_i F_i^T per particle at its unwrapped vertices (translation invariant).
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    for (const Particle3d& p : s.particles)
        shape_energy3d(p.shape, s.meshes[p.mesh], x, p.first, &g, nullptr);
    const int n = s.vertex_count();
    moment -= x.reshaped(3, n) * g.reshaped(3, n).transpose();
    interaction_energy3d(s, x, nullptr, nullptr, &moment);
    return moment / std::pow(*s.box, 3);
}

void shear_packing3d(DpmSystem3d& s, Eigen::VectorXd& x, double dgamma)
{
    shear_vertices<3>(s, x, dgamma);
}

void scale_packing3d(DpmSystem3d& s, Eigen::VectorXd& x, double f)
{
    scale_particle_centres<3>(s, x, f);
}

double packing_fraction3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    double volume = 0;
    for (const Particle3d& p : s.particles)
        volume += mesh_volume(s.meshes[p.mesh], x, p.first);
    return volume / std::pow(*s.box, 3);
}

} // namespace softgrain::dpm
