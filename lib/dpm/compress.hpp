// Uniaxial compression of one 2D elastic shell between two flat rigid plates, DPM section 9.3.4
// (Fig. 9.10): the bottom plate (y = 0) is fixed, the top plate (y = H) moves down by delta in steps, each
// followed by FIRE on shape + plate energy
//   U^plate = sum_{t=1,2} sum_i k_p/2 (sigma/2 - r_i^t)^2 Theta(sigma/2 - r_i^t),  k_p/k_c = 4,
// r_i^t = distance of vertex i from plate t. F_a = force of the particle on the top plate.
#pragma once

#include "dpm/system.hpp"

#include <vector>

namespace softgrain::dpm {

// Repulsion k_p/2 (sigma/2 - r)^2 of one vertex from a plate at height `y` facing +y (bottom) or -y (top).
struct PlateEnergy
{
    double kp, half_sigma, y, facing; // facing = +1: bottom plate (vertex above it); -1: top plate
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 2, 1>& r) const
    {
        const Scalar gap = Scalar(facing) * (r(1) - Scalar(y));
        const Scalar overlap = Scalar(half_sigma) - gap;
        return Scalar(0.5 * kp) * overlap * overlap;
    }
};

struct CompressionOptions
{
    int nodes = 100;
    double kl = 1.0;                          // k_l / k_c
    double kb = 1.0;                          // k_b / (k_c sigma^2)
    double ka = 1.0;                          // k_a a0^2 / (k_c sigma^2)
    double kp = 4.0;                          // k_p / k_c (paper)
    double delta_min = 1e-4, delta_max = 0.2; // compression delta / D, log-spaced
    int steps = 30;
};

struct CompressionSample
{
    double delta_over_d = 0; // delta / D
    double force = 0;        // F_a [k_c sigma]
    long iterations = 0;
};

struct CompressionResult
{
    std::vector<CompressionSample> samples;
    double diameter = 0; // D = 2 R + sigma [sigma]
    long iterations = 0;
};

// Vertex diameter sigma = 1 equals the rest edge length (neighbouring vertex disks touch); R from N.
CompressionResult compress_shell(const CompressionOptions& options);

} // namespace softgrain::dpm
