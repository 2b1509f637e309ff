// ParaView frames of 2D DPM scenes (`run --vtk`, core/vtk.hpp): a DpmSystem as VTK PolyData.
//
// Particles: polygons (one-vertex particles, the smooth disks, as vertex cells). In a periodic box each
// particle is drawn whole, shifted by whole box periods so that its centre (vertex mean) lies in the box (the
// parallelogram of box_outline under a Lees-Edwards strain).
// Point data: radius sigma/2 of the vertex disk [L], force = -dU/dx of the system's energy [E/L]. Cell data:
// particle_id, area_ratio a/a0 (eq. (9.1); NaN for one-vertex particles and a0 = 0) and vertices N_mu.
// Lengths in the scene's unit L (sigma of the small particles or the vertex diameter), z = 0.
//
// 3D particles: closed triangle meshes, each face a polygon (the central vertex of the elastic tetrahedra is
// not drawn). Point data: radius sigma/2 [L], force = -dU/dx of the body's energy (shape, contacts; not the
// plates) [E/L]. Cell data (per face, the particle's value): particle_id, volume_ratio v/v0 (v the volume the
// mesh encloses, v0 the preferred or rest volume). Spring networks (2D and 3D): nodes as vertex cells and
// springs as lines with spring_strain l/l0 - 1 (NaN on the nodes).
#pragma once

#include "core/vtk.hpp"
#include "dpm/laws/spring_network.hpp"
#include "dpm/system/mesh3d.hpp"
#include "dpm/system/system.hpp"
#include "dpm/system/system3d.hpp"

#include <vector>

namespace softgrain::dpm {

vtk::PolyData dpm_particles(const DpmSystem& system, const Eigen::VectorXd& x);

// A field over the vertices of a 2D system, flat like its coordinates (u(2v), u(2v + 1) at vertex v), as
// 3-vectors (z = 0) in the point order of dpm_particles (the vertex order), for PolyData::point_vectors: a
// mode or a displacement that ParaView's Warp By Vector applies to the particles.
std::vector<double> vertex_vectors(const Eigen::VectorXd& u);

// The contacts between the particles of a 2D system, one line per touching particle pair (m < b) from the
// centre (vertex mean) of m, as drawn by dpm_particles, to that of b's nearest image. The pair's force is
// that of interaction_energy (rough or smooth) on the two particles alone: F, the sum over m's vertices of
// -dU_pair/dx, split along the unit vector n from m's centre to b's. Cell data: normal_force -F.n (> 0:
// repulsion), tangential_force |F - (F.n) n| (the frictionless interaction still has one: the vertex forces
// do not point along the centre line), force F on m (3-vector), particle and other_particle. [E/L]
vtk::PolyData dpm_contacts(const DpmSystem& system, const Eigen::VectorXd& x);

// The box [0, L_x] x [0, L_y] (periodic, or walls) as one closed polyline; with a Lees-Edwards strain gamma
// the parallelogram of the sheared periodic box, spanned by (L_x, 0) and (gamma L_y, L_y).
vtk::PolyData box_outline(const Eigen::Vector2d& box, double lees_edwards_strain = 0);

// Two horizontal plates (bottom at y_bottom, top at y_top) from x_min to x_max as polylines, cell data
// plate_id 0 (bottom) and 1 (top).
vtk::PolyData plates(double x_min, double x_max, double y_bottom, double y_top);

// One 3D particle drawn as its mesh: the connectivity, its vertices x(3 first) ..., its vertex diameter, its
// volume v0 for volume_ratio, and a shift added to its points (periodic boxes: whole particles in the box).
struct MeshParticle
{
    const TriangleMesh* mesh = nullptr;
    int first = 0;
    double sigma = 1, v0 = 1;
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
};

// Meshes of 3D particles at coordinates x with the body's energy gradient (same size as x) for `force`.
vtk::PolyData mesh_particles(const std::vector<MeshParticle>& particles, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& gradient);

// The particles of a 3D system (force from total_energy3d, v0 the shape's preferred volume), each drawn
// whole with its centre (vertex mean) in the periodic box [0, L]^3 when there is one.
vtk::PolyData dpm_particles3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

// A 2D or 3D spring network at node coordinates x: nodes (vertex cells, radius 1/2) and springs (lines).
vtk::PolyData spring_network_body(const SpringNetwork& network, const Eigen::VectorXd& x);

// The periodic cube [0, L]^3 as its 12 edges (lines).
vtk::PolyData box_outline3d(double L);

// Two plates normal to z (bottom at z_bottom, top at z_top) over [low, high] in x and y as quadrilaterals,
// cell data plate_id 0 (bottom) and 1 (top).
vtk::PolyData plates3d(const Eigen::Vector2d& low, const Eigen::Vector2d& high, double z_bottom,
                       double z_top);

} // namespace softgrain::dpm
