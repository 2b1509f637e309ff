// ParaView frames of SPD scenes (`run --vtk`, core/vtk.hpp): the shells of a ShellModel as VTK PolyData.
//
// Particles (closed shells) are polygons. Point data: velocity [m/s], force (the total force of the last
// evaluation: internal, contact and applied, damping excluded) [N], contact_force (normal contact force
// received) [N], hinge_torque M [N m] and plastic_ratio |M|/M^Y (1 on a plastic hinge, 0 for an elastic
// shell). Cell data: particle_id (the shell's index in the model), area_ratio A/A0 (A0: the polygon area when
// the shell was made), core_pressure p [Pa] (eq. (4)) and elastic_energy W [J]. Walls (open, rigid shells)
// are polylines with point data velocity and force, and cell data wall_id; contacts are lines
// (shell_contacts). Lengths in m, z = 0.
#pragma once

#include "core/vtk.hpp"
#include "spd/shell_model.hpp"

#include <vector>

namespace softgrain::spd {

vtk::PolyData shell_particles(const ShellModel& model, const std::vector<int>& shells);
vtk::PolyData shell_walls(const ShellModel& model, const std::vector<int>& shells);

// The contacts of the last force evaluation (ShellModel::active_contacts) as lines from the contacting vertex
// to the closest point of the element it touches, with cell data normal_force f_n, tangential_force f_t [N]
// (eqs. (6)-(7)), force (on the vertex) [N], vertex and particle (the contacting vertex and its shell) and
// other_particle (the shell of the element).
vtk::PolyData shell_contacts(const ShellModel& model);

// A frame of three parts, "particles", "walls" and "contacts", with the given field data (e.g. the strain).
std::vector<vtk::Part> shell_frame(const ShellModel& model, const std::vector<int>& particles,
                                   const std::vector<int>& walls,
                                   const std::vector<std::pair<std::string, double>>& fields = {});

} // namespace softgrain::spd
