// Affine steps of periodic packings in 2D and 3D. The compression step of the jamming protocol (DPM
// sec. 9.4): a periodic packing scaled by f about the origin, i.e. the box side(s) and every particle's
// centre (the mean of its vertices) times f, the shapes unchanged, so that the packing fraction changes by
// f^-Dim. The simple shear step of sec. 9.4.3: x' = x + dgamma y for every vertex, with the Lees-Edwards
// strain of the box grown by dgamma. And the tiling of a periodic packing into a larger box.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <utility>

namespace softgrain::dpm {

// System: a DpmSystem (Dim = 2) or DpmSystem3d (Dim = 3) with a periodic box; x: the vertex coordinates.
template <int Dim, class System>
void scale_particle_centres(System& system, Eigen::VectorXd& x, double f)
{
    if (!system.box) throw std::logic_error("scale_packing: the system has no periodic box");
    for (const auto& p : system.particles) {
        auto v = x.segment(Dim * p.first, Dim * p.count).reshaped(Dim, p.count);
        const Eigen::Matrix<double, Dim, 1> centre = v.rowwise().mean();
        v.colwise() += (f - 1.0) * centre;
    }
    *system.box *= f;
}

// Simple shear step of sec. 9.4.3, x_{mu i}' = x_{mu i} + dgamma y_{mu i} (shapes sheared too, as in the
// paper), and the Lees-Edwards strain of the box grows by dgamma. System: as above.
template <int Dim, class System>
void shear_vertices(System& system, Eigen::VectorXd& x, double dgamma)
{
    if (!system.box) throw std::logic_error("shear_packing: the system has no periodic box");
    for (Eigen::Index v = 0; v < x.size() / Dim; ++v)
        x(Dim * v) += dgamma * x(Dim * v + 1);
    system.lees_edwards_strain += dgamma;
}

// Side of a periodic box along `axis`: the cube of the 3D systems, the rectangle of the 2D one.
inline double box_side(double cube, int)
{
    return cube;
}
inline double box_side(const Eigen::Vector2d& rectangle, int axis)
{
    return rectangle(axis);
}

// The periodic packing tiled k times along each axis into a box k times as large (k >= 1). Copy c = (c_x,
// c_y[, c_z]), 0 <= c_a < k, of every particle is shifted by the lattice vector sum_a c_a L_a e_a plus the
// Lees-Edwards offset gamma c_y L_y e_x (the image one box up is shifted by gamma L_y), so the tiles follow
// the sheared lattice and the strain stays gamma. Every vertex meets the same neighbours at the same
// separations as through the images of the old box: the energy is k^Dim times the old one, an equilibrium
// stays one at the same stress, and the dynamical matrix (eq. 9.28) is block diagonal over the k^Dim Bloch
// wave vectors 2 pi m / (k L) whose m = 0 block is the old matrix (each old mode, tiled, is a mode of the
// new packing). Copy 0 is the old packing in place; each copy lists the particles in the old order. What it
// is for: the cost of the spectrum of a large packing without jamming one (dpm.bench's `replicate`).
// System: as above, without anchors (fixed points in space do not tile).
template <int Dim, class System>
void replicate_periodic_packing(System& system, Eigen::VectorXd& x, int k)
{
    if (!system.box) throw std::logic_error("replicate_periodic_packing: the system has no periodic box");
    if (k < 1) throw std::logic_error("replicate_periodic_packing: k < 1");
    if constexpr (requires { system.anchors; })
        if (!system.anchors.empty())
            throw std::logic_error("replicate_periodic_packing: anchors do not tile");
    int copies = 1;
    for (int a = 0; a < Dim; ++a)
        copies *= k;
    const Eigen::Index n = x.size();
    const int vertices = system.vertex_count();
    const auto original = system.particles;
    Eigen::VectorXd tiled(copies * n);
    for (int c = 0; c < copies; ++c) {
        Eigen::Matrix<double, Dim, 1> shift;
        for (int a = 0, rest = c; a < Dim; ++a, rest /= k)
            shift(a) = (rest % k) * box_side(*system.box, a);
        shift(0) += system.lees_edwards_strain * shift(1);
        tiled.segment(c * n, n) = (x.reshaped(Dim, n / Dim).colwise() + shift).reshaped();
        if (c == 0) continue;
        for (auto p : original) {
            p.first += c * vertices;
            system.particles.push_back(p);
        }
    }
    *system.box *= k;
    x = std::move(tiled);
}

} // namespace softgrain::dpm
