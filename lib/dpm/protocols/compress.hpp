// Uniaxial compression of one body between two flat rigid plates, DPM section 9.3.4: in 2D (Fig. 9.10) an
// elastic shell (eq. 9.1) or a spring-network disk (spring_network.hpp); the 3D bodies of Fig. 9.11 use the
// same driver (compress3d.hpp). The plates are normal to the last axis (y in 2D, z in 3D): the bottom plate
// (height 0) is fixed, the top plate (height H) moves down by delta in steps, each followed by FIRE on
// body + plate energy, with the plate law
//   U^plate = sum_{t=1,2} sum_i k_p/2 (sigma/2 - r_i^t)^2 Theta(sigma/2 - r_i^t),  k_p/k_c = 4,
// r_i^t = distance of vertex i from plate t. F_a = force of the particle on the top plate.
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace softgrain::dpm {

// Repulsion k_p/2 (sigma/2 - r)^2 of one vertex from a plate at height `y` (along the last axis of r, in 2D
// or 3D) facing up (bottom plate) or down (top plate). Valid (non-zero) only for r < sigma/2: the caller
// applies Theta.
struct PlateEnergy
{
    double kp, half_sigma, y, facing; // facing = +1: bottom plate (vertex above it); -1: top plate
    template <class Scalar, int Dim>
    Scalar operator()(const Eigen::Matrix<Scalar, Dim, 1>& r) const
    {
        const Scalar gap = Scalar(facing) * (r(Dim - 1) - Scalar(y));
        const Scalar overlap = Scalar(half_sigma) - gap;
        return Scalar(0.5 * kp) * overlap * overlap;
    }
};

// The compression schedule: delta/D log-spaced from delta_min to delta_max in `steps` steps, or the given
// `compressions` delta/D when there are any, FIRE to an rms force per degree of freedom below
// force_tolerance and a kinetic energy per degree of freedom below kinetic_tolerance after each.
struct PlateSchedule
{
    double kp = 4.0; // k_p / k_c
    double delta_min = 1e-4, delta_max = 0.2;
    int steps = 30;
    double force_tolerance = 1e-12;     // [k_c sigma]
    double kinetic_tolerance = 1e-20;   // [k_c sigma^2]
    std::vector<double> compressions{}; // delta/D in order; empty: the log-spaced ones
    std::vector<double> deltas() const; // the delta/D of each step
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
    PlateSchedule schedule() const { return {kp, delta_min, delta_max, steps}; }
};

struct CompressionSample
{
    double delta_over_d = 0; // delta / D
    double force = 0;        // F_a [k_c sigma]
    long iterations = 0;
    int top_contacts = 0; // vertices touching the top plate
};

struct CompressionResult
{
    std::vector<CompressionSample> samples;
    double diameter = 0; // D = body height + sigma (the vertex disks included) [sigma]
    long iterations = 0;
    int springs = 0; // spring network only
};

// Energy of a body alone, adding its gradient when asked (FIRE needs no Hessian).
using BodyEnergy = std::function<double(const Eigen::VectorXd&, Eigen::VectorXd*)>;
// Called after each relaxed step with the body's coordinates, the top plate's height and the sample.
using PlateObserver = std::function<void(const Eigen::VectorXd&, double, const CompressionSample&)>;

// The protocol for a body of points of diameter sigma in Dim = 2 or 3 dimensions (coordinates x, point p at
// x(Dim p) ...): the body is lifted to rest on the bottom plate (lowest point at sigma/2), the top plate
// starts touching its highest point, D = initial height + sigma. FIRE with dt_max = 0.5/sqrt(lambda_max)
// (lambda_max: an upper bound of the body's stiffest mode, unit masses; the plate spring k_p is included).
// NumericalError when FIRE does not converge. observe, if given, sees each relaxed state.
template <int Dim>
CompressionResult compress_between_plates(Eigen::VectorXd x, const BodyEnergy& body, double sigma,
                                          double lambda_max, const PlateSchedule& schedule,
                                          const PlateObserver& observe = {});

// Vertex diameter sigma = 1 equals the rest edge length (neighbouring vertex disks touch); R from N.
// observe, if given, sees each relaxed state (PlateObserver).
CompressionResult compress_shell(const CompressionOptions& options, const PlateObserver& observe = {});
// The shell of compress_shell as a one-particle system, its vertex coordinates into x (before the lift onto
// the bottom plate).
DpmSystem compression_shell(const CompressionOptions& options, Eigen::VectorXd& x);

// Node diameter sigma = 1 = the lattice spacing.
CompressionResult compress_spring_network(const CompressionOptions& options,
                                          const PlateObserver& observe = {});

// Eq. (9.14) (Puttock and Thwaite, elastic cylinder of diameter D and length l between plates), in the
// paper's dimensionless form: delta~ = (4 F~ D~/pi)(1 + ln[pi/(D~^3 F~)]), F~ = F_a (1 - nu^2)/(E D^2),
// D~ = D/l, delta~ = delta/D. In 2D, F_a/l is the force per unit length f and E the 2D modulus, so that
// F~ D~ = f (1 - nu^2)/(E D). Valid for F~ D~^3 << pi (small contact width).
double cylinder_compression(double force_tilde, double d_tilde);

} // namespace softgrain::dpm
