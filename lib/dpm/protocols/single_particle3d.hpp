// A single 3D deformable particle of Table 9.1 (eq. 9.2) on a closed triangulated mesh, relaxed to a
// mechanical equilibrium exact to round-off (FIRE, then Newton steps on the exact Hessian), for the mode
// analysis of section 9.4.3 (Fig. 9.15a).
//
// Units: lengths in v0^(1/3) (the mesh is scaled to volume v0 = 1), energies in k_v v0^2 (k_v = 1); so
// k_a is in k_v v0^(2/3), k_b in k_v v0^2, gamma in k_v v0^(5/3), eigenvalues in k_v v0^(4/3) (the
// paper's lambda~ of section 9.4.3).
//   floppy:          k_v, k_a > 0, k_b = 0, gamma = 0
//   shell:           k_v, k_a, k_b > 0 (theta_e0 = the mesh's angles), gamma = 0
//   surface_tension: k_v, k_a > 0, k_b = 0, gamma > 0
// Rest state: v0 = 1, a_f0 = c times the (scaled) mesh's face areas with c = (A0/A_mesh)^(2/3), so that
// the preferred shape parameter (sum a_f0)^(3/2)/(6 sqrt(pi) v0) is A0 (A0 = A_mesh: the mesh's own).
#pragma once

#include "dpm/laws/shape_energy.hpp"
#include "dpm/laws/shape_energy3d.hpp"

#include <cstdint>
#include <optional>

namespace softgrain::dpm {

struct Stiffness3d
{
    double ka = 1, kb = 0.1, gamma = 0.01; // k_v = 1
};

struct SingleParticle3d
{
    TriangleMesh mesh;
    ShapeParameters3d shape;
    Eigen::VectorXd x;    // relaxed vertex coordinates (3N)
    double A0 = 0;        // preferred shape parameter used
    double A_mesh = 0;    // shape parameter of the undeformed mesh
    double force_max = 0; // largest force component left
    long fire_iterations = 0;
};

// Rest state of Table 9.1's model on the mesh at coordinates x (point v at x(3v)): v0 = its volume,
// a_f0 = c times its face areas with c = (A0/A_mesh)^(2/3), theta_e0 = its bending angles (shell only),
// k_v = kv, k_a, k_b (shell), gamma (surface_tension) from k. InputError if A0 < A_mesh (the mesh's own
// A^3D).
ShapeParameters3d model_shape3d(ShapeModel model, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                                double A0, double kv, const Stiffness3d& k);

// No `A0` selects the mesh's own shape parameter. The start is the mesh with every coordinate displaced
// uniformly by up to 0.05 of the mean edge length (seeded), so that floppy particles leave the symmetric
// (saddle) start.
SingleParticle3d single_particle3d_equilibrium(ShapeModel model, const TriangleMesh& mesh,
                                               std::optional<double> A0, const Stiffness3d& k,
                                               std::uint64_t seed);

} // namespace softgrain::dpm
