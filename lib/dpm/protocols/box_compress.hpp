// Uniaxial compression of soft disks and of deformable particles in a square box with repulsive walls, the
// protocol pictured in DPM Fig. 9.4 (section 9.1): both packings are first compressed isotropically to the
// same wall pressure P0, then the top wall moves down by 20 % of the box height in steps, FIRE after each.
//
// Walls: U^wall = sum_i k_c/2 (sigma_i/2 - r_i^wall)^2 Theta(sigma_i/2 - r_i^wall) for each vertex (a disk is
// a one-vertex particle of diameter sigma_i), the plate law of section 9.3.4 with k_p = k_c on four sides.
// Disks: rough repulsion (9.4) between the one-vertex particles with spring k_disk; deformable particles:
// rough elastic shells of Table 9.1 (vertex diameter sigma = 1, k_c = 1). "The same bulk modulus"
// (decision dpm-box-compress): k_disk = k_a a0 of the small deformable particle, its area modulus.
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>
#include <vector>

namespace softgrain::dpm {

// Repulsion k/2 (sigma/2 - gap)^2 of one point from a straight wall normal to `axis` (0 = x, 1 = y) at
// `position`, facing +1 (the point is on the larger side) or -1.
struct WallEnergy
{
    double k, half_sigma, position, facing;
    int axis;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 2, 1>& r) const
    {
        const Scalar overlap = Scalar(half_sigma) - Scalar(facing) * (r(axis) - Scalar(position));
        return Scalar(0.5 * k) * overlap * overlap;
    }
};

struct BoxCompressOptions
{
    bool deformable = false; // false: soft disks; true: deformable particles
    int particles = 32;      // 50:50 bidisperse, size ratio 1.4
    int nodes_small = 16, nodes_large = 22;
    double pressure_start = 1e-2; // P0, wall force per length [k_a a0 of the small DP = k_disk]
    double strain = 0.2;          // uniaxial compression of the box height
    int steps = 20;
    std::uint64_t seed = 1;
};

struct BoxState
{
    Eigen::VectorXd x;
    double width = 0, height = 0;
    double pressure_x = 0, pressure_y = 0; // wall force per length on the side and top walls [k_disk]
};

struct BoxCompressResult
{
    DpmSystem system;
    std::vector<BoxState> states; // after the isotropic stage, then after each uniaxial step
    double pressure_unit = 1;     // k_disk = k_a a0 [k_c]
    double diameter_small = 0; // outer diameter of a small particle (disk, or polygon + vertex disks) [sigma]
    long iterations = 0;
};

BoxCompressResult compress_in_box(const BoxCompressOptions& options);

// Deepest overlap sigma_ij - r between vertices of different particles [sigma].
double largest_interparticle_overlap(const DpmSystem& system, const Eigen::VectorXd& x);
// Mean number of overlapping vertex pairs per pair of particles in contact (1 for disks; >= 2 on a facet).
double vertex_contacts_per_particle_contact(const DpmSystem& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
