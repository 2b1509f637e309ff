// The compression step of the jamming protocol (DPM sec. 9.4), in 2D and 3D: a periodic packing scaled by f
// about the origin, i.e. the box side(s) and every particle's centre (the mean of its vertices) times f, the
// shapes unchanged, so that the packing fraction changes by f^-Dim.
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

} // namespace softgrain::dpm
