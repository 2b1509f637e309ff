// Uniaxial compression of one 2D body between two flat rigid plates, DPM section 9.3.4 (Fig. 9.10): an
// elastic shell (eq. 9.1) or a spring-network disk (spring_network.hpp). The bottom plate (y = 0) is fixed,
// the top plate (y = H) moves down by delta in steps, each followed by FIRE on body + plate energy
//   U^plate = sum_{t=1,2} sum_i k_p/2 (sigma/2 - r_i^t)^2 Theta(sigma/2 - r_i^t),  k_p/k_c = 4,
// r_i^t = distance of vertex i from plate t. F_a = force of the particle on the top plate.
#pragma once

#include "dpm/system.hpp"

#include <cstdint>
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
    // Shell:
    int nodes = 100;
    double kl = 1.0; // k_l / k_c
    double kb = 1.0; // k_b / (k_c sigma^2)
    double ka = 1.0; // k_a a0^2 / (k_c sigma^2)
    // Spring network (Fig. 9.10a: 1100 nodes, k/k_c = 1):
    int network_nodes = 1100;
    double network_jitter = 0.2; // node displacement / lattice spacing
    double network_k = 1.0;      // spring k / k_c
    std::uint64_t seed = 1;
    // Both:
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
    double diameter = 0; // D = body height + sigma (the vertex disks included) [sigma]
    long iterations = 0;
    int springs = 0; // spring network only
};

// Vertex diameter sigma = 1 equals the rest edge length (neighbouring vertex disks touch); R from N.
CompressionResult compress_shell(const CompressionOptions& options);

// Node diameter sigma = 1 = the lattice spacing.
CompressionResult compress_spring_network(const CompressionOptions& options);

// Eq. (9.14) (Puttock and Thwaite, elastic cylinder of diameter D and length l between plates), in the
// paper's dimensionless form: delta~ = (4 F~ D~/pi)(1 + ln[pi/(D~^3 F~)]), F~ = F_a (1 - nu^2)/(E D^2),
// D~ = D/l, delta~ = delta/D. In 2D, F_a/l is the force per unit length f and E the 2D modulus, so that
// F~ D~ = f (1 - nu^2)/(E D). Valid for F~ D~^3 << pi (small contact width).
double cylinder_compression(double force_tilde, double d_tilde);

} // namespace softgrain::dpm
