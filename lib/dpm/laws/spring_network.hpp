// The spring networks of DPM section 9.3.4: nodes joined by linear springs,
// U = sum_springs k/2 (|r_i - r_j| - l_ij0)^2 (the edge penalty of eq. 9.1, in 2D or 3D), the bulk-elastic
// references against which the elastic shells are compared: a disk in 2D (Fig. 9.10a), a ball in 3D
// (Fig. 9.11a).
// Sign: U >= 0; spring_network_energy adds the gradient dU/dx = minus the forces. Units: lengths in the
// node spacing a [L], k [E/L^2], U [E]. Valid for springs of non-zero length (the gradient of |r_i - r_j|
// is singular at r_i = r_j); a spring pulls and pushes alike, with no bending or contact between nodes.
//
// 2D disk:
// Construction (decision dpm-spring-network): the `nodes` points of a triangular lattice of spacing a = 1
// nearest to the centre; springs join lattice neighbours; each interior node (6 springs) is displaced by a
// seeded uniform random vector of length <= jitter a, the boundary keeps the lattice's mirror symmetry; rest
// length = distance after the displacement (a stress-free disk).
// Continuum moduli of the ordered lattice (plane stress, 2D): E = 2k/sqrt(3) [force/length], nu = 1/3.
//
// 3D ball (decision dpm-spring-network3d): nodes on the sphere of radius R (a Fibonacci spiral, one node per
// area a^2) and inside it (random sequential addition with minimum distance 0.7 a in the ball of radius
// R - 0.35 a, density 1/a^3), a = 1 the node spacing and diameter; springs join every pair closer than
// cutoff a; rest length = initial distance (stress-free). Moduli of the affine (Cauchy) estimate of an
// isotropic central-force network: lambda = mu = sum_s k l_s^2 /(15 V), so E = sum_s k l_s^2/(6 V), nu = 1/4.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <vector>

namespace softgrain::dpm {

struct Spring
{
    int i = 0, j = 0;
    double rest_length = 0;
};

// One spring k/2 (|r_1 - r_0| - l0)^2 between the two points of x = (r_0, r_1) in Dim dimensions.
template <int Dim>
struct SpringEnergy
{
    double k, l0;
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 2 * Dim, 1>& x) const
    {
        using std::sqrt;
        const Eigen::Matrix<Scalar, Dim, 1> d = x.template tail<Dim>() - x.template head<Dim>();
        const Scalar length = sqrt(d.squaredNorm());
        const Scalar deviation = length - Scalar(l0);
        return Scalar(0.5 * k) * deviation * deviation;
    }
};

struct SpringNetwork
{
    Eigen::VectorXd x; // node positions, node v at x(dim v) ... x(dim v + dim - 1); centred at the origin
    std::vector<Spring> springs;
    double k = 1; // spring stiffness [k_c]
    int dim = 2;
    int node_count() const { return static_cast<int>(x.size() / dim); }
};

SpringNetwork disordered_triangular_disk(int nodes, double jitter, double k, std::uint64_t seed);

// The 3D ball of about `nodes` nodes (the count is exact up to the rounding of the surface/interior split).
SpringNetwork disordered_sphere_network(int nodes, double cutoff, double k, std::uint64_t seed);

// Spring energy; adds its gradient into `gradient` when given.
double spring_network_energy(const SpringNetwork& network, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient);

// Young's modulus and Poisson ratio of the ordered triangular lattice of springs k (2D, plane stress).
inline double triangular_lattice_young_modulus(double k)
{
    return 2 * k / std::sqrt(3.0);
}
inline constexpr double triangular_lattice_poisson_ratio = 1.0 / 3.0;

// Affine estimate of Young's modulus of a 3D isotropic central-force network of volume `volume`:
// sum_s k l_s^2/(6 V); its Poisson ratio is 1/4 (Cauchy relation lambda = mu).
double affine_network_young_modulus(const SpringNetwork& network, double volume);
inline constexpr double affine_network_poisson_ratio = 0.25;

} // namespace softgrain::dpm
