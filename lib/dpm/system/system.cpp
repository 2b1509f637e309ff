#include "dpm/system/system.hpp"

#include "core/errors.hpp"
#include "dpm/laws/interactions.hpp"
#include "dpm/system/scale_packing.hpp"

#include <stdexcept>

namespace softgrain::dpm {

MemoryEstimate dpm_vertex_memory(double vertices, const std::string& what)
{
    return per_item_memory(vertices, 5.6e3, what);
}

InteractionKind interaction_from_name(const std::string& name)
{
    if (name == "rough") return InteractionKind::rough;
    if (name == "smooth") return InteractionKind::smooth;
    throw InputError("interaction = '" + name + "': allowed rough | smooth");
}

void DpmSystem::add_particle(const Eigen::Matrix2Xd& vertices, double sigma, const ShapeParameters& shape,
                             Eigen::VectorXd& x)
{
    Particle p;
    p.first = vertex_count();
    p.count = static_cast<int>(vertices.cols());
    p.sigma = sigma;
    p.shape = shape;
    particles.push_back(p);
    x.conservativeResize(2 * vertex_count());
    x.segment(2 * p.first, 2 * p.count) = vertices.reshaped();
}

namespace {

// k/2 |r - r0|^2 of one anchored vertex.
struct AnchorEnergy
{
    double k;
    Eigen::Vector2d r0;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 2, 1>& r) const
    {
        const Scalar dx = r(0) - r0.x(), dy = r(1) - r0.y();
        return Scalar(0.5 * k) * (dx * dx + dy * dy);
    }
};

} // namespace

double total_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                    HessianSink hessian, unsigned parts)
{
    double energy = 0;
    if (parts & shape_part)
        for (const Particle& p : system.particles)
            energy += shape_energy(p.shape, x, p.first, p.count, gradient, hessian);
    if ((parts & interaction_part) && system.interaction != InteractionKind::none)
        energy += interaction_energy(system, x, gradient, hessian);
    if (parts & anchor_part)
        for (const Anchor& a : system.anchors) {
            const std::array<int, 1> point{a.vertex};
            energy += add_local_term<2, 1>(AnchorEnergy{a.k, a.position}, point, gather<2, 1>(x, point),
                                           gradient, hessian);
        }
    return energy;
}

Eigen::Matrix2Xd regular_polygon(int n, double r, const Eigen::Vector2d& c, double phase)
{
    Eigen::Matrix2Xd v(2, n);
    for (int i = 0; i < n; ++i) {
        const double angle = phase + 2.0 * std::numbers::pi * i / n;
        v.col(i) = c + r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
    return v;
}

Eigen::Vector2d DpmSystem::image(const Eigen::Vector2d& d) const
{
    return box ? lees_edwards_image(d, *box, lees_edwards_strain) : d;
}

void shear_packing(DpmSystem& system, Eigen::VectorXd& x, double dgamma)
{
    shear_vertices<2>(system, x, dgamma);
}

void scale_packing(DpmSystem& system, Eigen::VectorXd& x, double f)
{
    scale_particle_centres<2>(system, x, f);
}

} // namespace softgrain::dpm
