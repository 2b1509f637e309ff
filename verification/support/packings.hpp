// Packings shared by the DPM tests: an fcc crystal of one-vertex particles (exact shear modulus) and small
// jammed 2D and 3D packings polished to round-off forces (the reference systems of the mode and modulus tests).
#pragma once

#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/system/system3d.hpp"

#include <cmath>
#include <cstdint>
#include <string>

namespace softgrain::verification {

// n^3 cubic cells of side sqrt(2) a, four one-vertex particles (sigma = 1, k_c = 1, no shape energy) per
// cell, in a periodic cube.
inline dpm::DpmSystem3d fcc_crystal(double a, int n, Eigen::VectorXd& x)
{
    dpm::DpmSystem3d s;
    s.kc = 1.0;
    const double c = std::sqrt(2.0) * a;
    s.box = n * c;
    dpm::TriangleMesh point;
    point.vertices = Eigen::Matrix3Xd::Zero(3, 1);
    s.meshes.push_back(point);
    const Eigen::Vector3d basis[4] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                for (const Eigen::Vector3d& b : basis)
                    s.add_particle(0, c * (Eigen::Vector3d(i + 0.25, j + 0.25, k + 0.25) + b), 1.0,
                                   dpm::ShapeParameters3d{}, x);
    return s;
}

// `particles` deformable particles of 6 and 10 vertices of `model`, jammed by the dpm.jam protocol at
// P_t = 1e-5 k_a a0 and Newton-polished to round-off forces (polish_for_modes).
inline dpm::JamResult polished_packing2d(dpm::JamModel model, int particles, std::uint64_t seed)
{
    dpm::JamOptions o;
    o.model = model;
    o.particles = particles;
    o.nodes_small = 6;
    o.nodes_large = 10;
    o.pressure_onset = o.pressure_max = 1e-5;
    o.pressures = 0;
    o.seed = seed;
    dpm::JamResult r = dpm::jam(o);
    dpm::polish_for_modes(r.system, r.x, r.pressure_unit);
    return r;
}

// `particles` icosahedral shells jammed by the 3D protocol at P_t = 1e-5 k_v v0 and Newton-polished to
// round-off forces.
inline dpm::Jam3dResult polished_packing3d(int particles, std::uint64_t seed)
{
    dpm::Jam3dOptions o;
    o.particles = particles;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-5;
    o.seed = seed;
    dpm::Jam3dResult j = dpm::jam3d(o);
    dpm::polish_for_modes([&j](const Eigen::VectorXd& y, Eigen::VectorXd* g,
                               Eigen::MatrixXd* h) { return dpm::total_energy3d(j.system, y, g, h); },
                          j.x, j.pressure_unit);
    return j;
}

} // namespace softgrain::verification
