// A 3D deformable-particle system, DPM sections 9.3-9.4 in 3D: particles are closed triangulated meshes
// (mesh3d.hpp) with the shape energy of eq. (9.2) (shape_energy3d.hpp), repelling each other through their
// vertices (rough interaction, eqs. 9.3-9.4 in 3D: every vertex a sphere of diameter sigma_mu),
//
//   U_int = sum_{mu < beta} sum_{i in mu, j in beta} k_c/2 (sigma_mb - r_ij)^2 Theta(sigma_mb - r_ij),
//   sigma_mb = (sigma_mu + sigma_beta)/2,
//
// or, with interaction = smooth, through the vertex-face repulsion of sphero-polyhedra (interactions3d.hpp),
// in open space or a periodic cubic box of side L, optionally sheared (Lees-Edwards). r_ij is the
// minimum-image distance of each vertex pair (decision dpm-3d-vertex-image): exact for
// L > 2 max sigma (1 + |gamma|), whatever the size of the particles.
//
// State: one flat Eigen::VectorXd x, vertex v at x(3v) ... x(3v + 2); each particle's vertices are stored
// unwrapped (the particle whole). The total energy, its gradient (= minus the forces) and its exact Hessian
// (the dynamical matrix of eq. 9.28 for unit masses) are assembled from the same local AutoDiff terms as in
// 2D (local_derivatives.hpp); the vertex spring is the 2D one in Dim = 3 (interactions.hpp).
// Units: lengths [L], energies [E], k_c [E/L^2]; stress and pressure [E/L^3].
#pragma once

#include "dpm/laws/shape_energy3d.hpp"
#include "dpm/system/mesh3d.hpp"
#include "dpm/system/system.hpp"
#include "dpm/system/vertex_pairs3d.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace softgrain::dpm {

struct Particle3d
{
    int first = 0;    // index of its first vertex
    int mesh = 0;     // index of its connectivity in DpmSystem3d::meshes (vertex v -> point first + v)
    int count = 0;    // number of vertices N_mu
    double sigma = 0; // vertex diameter sigma_mu [L]
    ShapeParameters3d shape;
};

struct DpmSystem3d
{
    std::vector<TriangleMesh> meshes; // connectivities, shared by the particles that use them
    std::vector<Particle3d> particles;
    double kc = 1.0;           // contact stiffness k_c [E/L^2]; 0 switches the interaction off
    std::optional<double> box; // side L of the periodic cubic box (corner at the origin); absent: open space
    // Lees-Edwards shear strain gamma of the box (sec. 9.4.3, x sheared along y): the images one box up in y
    // are shifted by gamma L in x (lees_edwards_image, core/neighbour_list.hpp). 0: the plain periodic cube.
    double lees_edwards_strain = 0;
    // rough: vertex spheres (eqs. 9.3-9.4); smooth: vertex against faces (interactions3d.hpp); none: off.
    InteractionKind interaction = InteractionKind::rough;
    // The vertex-level Verlet list of the interaction (vertex_pairs3d.hpp): a cache kept between
    // evaluations (list_cache.hpp), which every contact loop, rough or smooth, traverses.
    ListCache<VertexPairList3d, DpmSystem3d> contacts;

    int vertex_count() const
    {
        return particles.empty() ? 0 : particles.back().first + particles.back().count;
    }
    // Nearest periodic image of a separation under the Lees-Edwards strain (d itself without a box).
    Eigen::Vector3d image(const Eigen::Vector3d& d) const;
    // Appends a particle on meshes[mesh] with the given vertices (3 x N, in the mesh's vertex order).
    void add_particle(int mesh, const Eigen::Matrix3Xd& vertices, double sigma,
                      const ShapeParameters3d& shape, Eigen::VectorXd& x);
    // The vertices of particle p as a 3 x N view of x.
    Eigen::Matrix3Xd vertices(const Particle3d& p, const Eigen::VectorXd& x) const;
};

// Interaction energy (rough: the formula above; smooth: interactions3d.hpp); adds its gradient and
// Hessian when given. `virial`, when given, accumulates the force moment sum r_a F_b of every contact at
// its minimum-image coordinates (the pair part of the 3D analogue of eq. 9.26).
double interaction_energy3d(const DpmSystem3d& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                            HessianSink hessian, Eigen::Matrix3d* virial = nullptr);

// Shape energies (eq. 9.2) of all particles plus the interaction; adds the gradient and the Hessian.
double total_energy3d(const DpmSystem3d& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                      HessianSink hessian);

// Stress tensor of a static periodic packing, the 3D analogue of eq. (9.26):
//   Sigma_ab = (1/L^3) [ sum_mu sum_i r_{mu i,a} F^shape_{mu i,b} - sum_{contacts} r_{ij,a} F_{ij,b} ],
// positive in compression; pressure P = Tr(Sigma)/3 [E/L^3]. Equal to -dU/dV under a homogeneous dilation
// of every coordinate and the box (verification/dpm/protocols/jamming3d.cpp).
Eigen::Matrix3d stress_tensor3d(const DpmSystem3d& system, const Eigen::VectorXd& x);
inline double pressure3d(const Eigen::Matrix3d& stress)
{
    return stress.trace() / 3.0;
}

// Simple shear step of sec. 9.4.3: x_i += dgamma y_i for every vertex, and the Lees-Edwards strain grows by
// dgamma. The system must have a box.
void shear_packing3d(DpmSystem3d& system, Eigen::VectorXd& x, double dgamma);

// Affine compression of a periodic packing by the factor f: every particle's centre (vertex mean) is scaled
// by f and its shape kept; the box side is scaled by f (the compression step of section 9.4).
void scale_packing3d(DpmSystem3d& system, Eigen::VectorXd& x, double f);

// Packing fraction sum_mu v_mu / L^3 with v_mu the volume enclosed by particle mu's mesh (decision
// dpm-3d-jam-packing-fraction: the vertex spheres' caps outside the mesh are not counted).
double packing_fraction3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

// Number of vertex contacts (r_ij < sigma_mb) of each particle; smooth: vertex-surface contacts
// (smooth_contact_counts3d).
std::vector<int> contact_counts3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

// The touching pairs at x: rough, the vertex pairs (i, j) of contact_counts3d in (i, j) order; smooth, the
// (vertex, particle) pairs of smooth_touching_pairs3d. What a relaxation step may change outside the
// Hessian's model (newton_relax.hpp).
std::vector<std::pair<int, int>> touching_pairs3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
