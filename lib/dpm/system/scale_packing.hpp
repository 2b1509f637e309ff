// Affine steps of periodic packings in 2D and 3D. The compression step of the jamming protocol (DPM
// sec. 9.4): a periodic packing scaled by f about the origin, i.e. the box side(s) and every particle's
// centre (the mean of its vertices) times f, the shapes unchanged, so that the packing fraction changes by
// f^-Dim. The simple shear step of sec. 9.4.3: x' = x + dgamma y for every vertex, with the Lees-Edwards
// strain of the box grown by dgamma.
#pragma once

#include <Eigen/Core>

#include <stdexcept>

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

} // namespace softgrain::dpm
