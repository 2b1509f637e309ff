// One particle of Table 9.1 at mechanical equilibrium, exact to round-off (for mode counting, Fig. 9.14a).
//
// Start: the regular polygon of area a0. A floppy particle with A0 > A_min has no regular rest shape; its
// vertices are displaced at random (seeded, 5 % of l0) to leave the symmetric saddle. FIRE relaxes it,
// Newton steps (modes.hpp) polish the equilibrium until every force component is below 1e-14 k_a a0^(3/2).
// Throws NumericalError if either stage fails.
#pragma once

#include "core/fire.hpp"
#include "dpm/system/system.hpp"

#include <cstdint>

namespace softgrain::dpm {

struct SingleParticle
{
    DpmSystem system;
    Eigen::VectorXd x;
    long fire_iterations = 0;
    double force_max = 0; // largest force component after polishing
};

SingleParticle single_particle_equilibrium(ShapeModel model, int n, double a0, double A0,
                                           const ShapeStiffness& k, std::uint64_t seed);

} // namespace softgrain::dpm
