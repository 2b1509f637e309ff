// The spring-network disk of DPM section 9.3.4 (Fig. 9.10a): a disordered triangular lattice of nodes joined
// by linear springs, U = sum_springs k/2 (|r_i - r_j| - l_ij0)^2 (the edge penalty of eq. 9.1 reused), the
// bulk-elastic reference against which the elastic shell is compared.
//
// Construction (decision dpm-spring-network): the `nodes` points of a triangular lattice of spacing a = 1
// nearest to the centre; springs join lattice neighbours; each interior node (6 springs) is displaced by a
// seeded uniform random vector of length <= jitter a, the boundary keeps the lattice's mirror symmetry; rest
// length = distance after the displacement (a stress-free disk).
// Continuum moduli of the ordered lattice (plane stress, 2D): E = 2k/sqrt(3) [force/length], nu = 1/3.
#pragma once

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace softgrain::dpm {

struct Spring
{
    int i = 0, j = 0;
    double rest_length = 0;
};

struct SpringNetwork
{
    Eigen::VectorXd x; // node positions, node v at x(2v), x(2v+1); centred at the origin
    std::vector<Spring> springs;
    double k = 1; // spring stiffness [k_c]
    int node_count() const { return static_cast<int>(x.size() / 2); }
};

SpringNetwork disordered_triangular_disk(int nodes, double jitter, double k, std::uint64_t seed);

// Spring energy; adds its gradient into `gradient` when given.
double spring_network_energy(const SpringNetwork& network, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient);

// Young's modulus and Poisson ratio of the ordered triangular lattice of springs k (2D, plane stress).
inline double triangular_lattice_young_modulus(double k)
{
    return 2 * k / std::sqrt(3.0);
}
inline constexpr double triangular_lattice_poisson_ratio = 1.0 / 3.0;

} // namespace softgrain::dpm
