// ParaView frames of VSM scenes (`run --vtk`, core/vtk.hpp): the particles of a Model as points, and the
// faces on which a displacement is prescribed (plates, the punch) as their own part.
//
// particles: one point per real particle at its current position x_a [m] (vertex cells). Point data:
// displacement x_a - X_a [m]; velocity, leapfrog's half-step v_a(t - dt/2) [m/s]; deformation_gradient F_a
// (eq. (6) with the ghost branch vectors of eq. (24); 9 components, row-major F_11 F_12 F_13 F_21 ...);
// cauchy_stress sigma_a = P_a F_a^T / J_a of the neo-Hookean mean stress (eq. (48), elastic part; 9
// components) [Pa]; pressure p_a = -tr(sigma_a)/3 [Pa] (Model::pressures, the Voronoi pressure of Fig. 10);
// von_mises sqrt(3/2 s:s) [Pa]; volume_ratio J_a = det F_a; voronoi_volume V_a, the reference Voronoi cell
// (section 2.1) [m^3]. Cell data: particle_id.
//
// walls: each face of the domain whose boundary kind prescribes a displacement (total, symmetric or
// antisymmetric, eq. (14)) as a quadrilateral, its corners W moved by D u_bar(label, W, t); traction and
// free faces are not drawn (the particles show them). Cell data: face_label (the boundary-condition label)
// and boundary_kind (1 total, 2 symmetric, 3 antisymmetric).
#pragma once

#include "core/vtk.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/vsm_model.hpp"

#include <string>
#include <utility>
#include <vector>

namespace softgrain::vsm {

vtk::PolyData vsm_particles(const Model& model, const Points<3>& x, const Points<3>& v, double t);
vtk::PolyData vsm_walls(const Model& model, double t);

// A frame: "particles", and "walls" when the model has a face with a prescribed displacement; field data
// time [s], step and the given fields on every part.
std::vector<vtk::Part> vsm_frame(const Model& model, const Leapfrog& integrator,
                                 const std::vector<std::pair<std::string, double>>& fields = {});
// The same at positions x, velocities v, time t and step (a state that no integrator holds: a static test).
std::vector<vtk::Part> vsm_frame(const Model& model, const Points<3>& x, const Points<3>& v, double t,
                                 long step, const std::vector<std::pair<std::string, double>>& fields = {});

} // namespace softgrain::vsm
