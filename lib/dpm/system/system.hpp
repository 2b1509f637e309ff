// A 2D deformable-particle system: particles (contiguous ranges of a flat vertex array), their shape
// energies (eq. 9.1), the interaction between particles (rough eq. 9.3-9.4 or smooth eq. 9.5-9.9) and
// harmonic anchors (the constraint springs of the simple-shear test, section 9.3.3).
//
// State: one flat Eigen::VectorXd x, vertex v at x(2v), x(2v+1); each particle's vertices are stored
// counter-clockwise and unwrapped. The total energy, its gradient (= minus the forces) and its Hessian
// (the dynamical matrix of eq. 9.28 for unit masses) are all assembled from the same local terms.
#pragma once

#include "core/neighbour_list.hpp"
#include "core/resources.hpp"
#include "dpm/laws/shape_energy.hpp"
#include "dpm/system/contact_list.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace softgrain::dpm {

// The memory of a 2D DpmSystem and its FIRE relaxation: 5.6 kB per vertex, measured as the growth of peak
// RSS between dpm.jam runs of 100 and 1600 particles (10 and 14 vertices).
MemoryEstimate dpm_vertex_memory(double vertices, const std::string& what);

enum class InteractionKind { none, rough, smooth };
InteractionKind interaction_from_name(const std::string& name); // "rough" | "smooth"

struct Particle
{
    int first = 0;    // index of its first vertex
    int count = 0;    // number of vertices N_mu
    double sigma = 0; // vertex diameter sigma_mu [L]
    ShapeParameters shape;
};

// Harmonic constraint k/2 |r_v - r0|^2 on one vertex (U^constraint of section 9.3.3 with k = k_constraint).
struct Anchor
{
    int vertex = 0;
    Eigen::Vector2d position = Eigen::Vector2d::Zero();
    double k = 0;
};

struct DpmSystem
{
    std::vector<Particle> particles;
    InteractionKind interaction = InteractionKind::none;
    double kc = 1.0; // contact stiffness k_c [E/L^2]
    std::vector<Anchor> anchors;
    // Sides (L_x, L_y) of a periodic rectangular box (minimum image between particles); absent: open space.
    // Particles are kept whole (unwrapped); the box must exceed twice the reach of any particle pair.
    std::optional<Eigen::Vector2d> box;
    // Lees-Edwards shear strain gamma of the box (section 9.4.3): the image above is shifted by gamma L_y in
    // x.
    double lees_edwards_strain = 0;
    // The vertex-level Verlet list of the interaction (contact_list.hpp): a cache kept between evaluations,
    // which every contact loop (energies, forces, Hessians, stress, contact counts) traverses.
    ContactCache contacts;

    int vertex_count() const
    {
        return particles.empty() ? 0 : particles.back().first + particles.back().count;
    }
    // Nearest periodic image of a separation (Lees-Edwards minimum image); d itself without a box.
    Eigen::Vector2d image(const Eigen::Vector2d& d) const;
    // Appends a particle with the given vertices (2 x n, counter-clockwise).
    void add_particle(const Eigen::Matrix2Xd& vertices, double sigma, const ShapeParameters& shape,
                      Eigen::VectorXd& x);
};

// Affine compression of a periodic packing by the factor f: every particle's centre (vertex mean) is scaled
// by f and its shape kept; the box sides are scaled by f. The system must have a box.
void scale_packing(DpmSystem& system, Eigen::VectorXd& x, double f);

// Parts of the total energy, so that each can be evaluated alone.
enum EnergyPart : unsigned { shape_part = 1u, interaction_part = 2u, anchor_part = 4u, all_parts = 7u };

// Total energy of the parts selected; adds the gradient and the Hessian when they are given.
double total_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                    HessianSink hessian, unsigned parts = all_parts);

// Minimum image of a separation in a periodic rectangular box of sides L = (L_x, L_y).
inline Eigen::Vector2d minimum_image(const Eigen::Vector2d& d, const Eigen::Vector2d& L)
{
    return d - (L.array() * (d.array() / L.array()).round()).matrix();
}

// The periodic image of a point in the box [0, L_x) x [0, L_y) (for drawing packings).
inline Eigen::Vector2d wrap_into_box(const Eigen::Vector2d& p, const Eigen::Vector2d& L)
{
    return p - (L.array() * (p.array() / L.array()).floor()).matrix();
}

// Simple shear step of section 9.4.3: x_i += dgamma y_i for every vertex, and the Lees-Edwards strain grows
// by dgamma. The system must have a box.
void shear_packing(DpmSystem& system, Eigen::VectorXd& x, double dgamma);

// Vertices of a regular n-gon of circumradius r centred at c, counter-clockwise, vertex 0 at angle phase.
Eigen::Matrix2Xd regular_polygon(int n, double r, const Eigen::Vector2d& c, double phase);

} // namespace softgrain::dpm
