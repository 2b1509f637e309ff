// ParaView frames of 2D DPM scenes (`run --vtk`, core/vtk.hpp): a DpmSystem as VTK PolyData.
//
// Particles: polygons (one-vertex particles, the smooth disks, as vertex cells). In a periodic box each
// particle is drawn whole, shifted by whole box sides so that its centre (vertex mean) lies in the box.
// Point data: radius sigma/2 of the vertex disk [L], force = -dU/dx of the system's energy [E/L]. Cell data:
// particle_id, area_ratio a/a0 (eq. (9.1); NaN for one-vertex particles and a0 = 0) and vertices N_mu.
// Lengths in the scene's unit L (sigma of the small particles or the vertex diameter), z = 0.
#pragma once

#include "core/vtk.hpp"
#include "dpm/system.hpp"

namespace softgrain::dpm {

vtk::PolyData dpm_particles(const DpmSystem& system, const Eigen::VectorXd& x);

// The periodic box [0, L_x] x [0, L_y] as one closed polyline.
vtk::PolyData box_outline(const Eigen::Vector2d& box);

// Two horizontal plates (bottom at y_bottom, top at y_top) from x_min to x_max as polylines, cell data
// plate_id 0 (bottom) and 1 (top).
vtk::PolyData plates(double x_min, double x_max, double y_bottom, double y_top);

} // namespace softgrain::dpm
