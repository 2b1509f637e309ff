// The shape energies of a system's particles (eqs. 9.1 and 9.2), summed over particles, in parallel when the
// work pays for the threads.
//
// Each particle's shape terms add only to its own vertices' gradient, so particles can run on different
// threads without a race. The result is bit-identical for every thread count: each particle's terms are
// summed in the same order as in the serial loop, and the particle energies are added in particle order
// starting from 0, as the serial loop does.
#pragma once

#include <omp.h>

#include <cstddef>
#include <vector>

namespace softgrain::dpm {

// energy_of(m): the shape energy of particle m, adding its gradient. `parallel`: split the particles over
// the OpenMP threads (static schedule). With one thread the serial loop runs: the parallel loop's team and
// buffer cost 5 % of a 3D FIRE run of 8 icosahedral shells (96 vertices) on one thread, and 8-28 % of 2D
// runs of 768 and 304 vertices (dpm.bench).
template <class EnergyOf>
double sum_over_particles(std::size_t particles, bool parallel, const EnergyOf& energy_of)
{
    double total = 0;
    if (!parallel || omp_get_max_threads() == 1) {
        for (std::size_t m = 0; m < particles; ++m)
            total += energy_of(m);
        return total;
    }
    std::vector<double> energies(particles);
    const auto count = static_cast<long>(particles);
#pragma omp parallel for schedule(static)
    for (long m = 0; m < count; ++m)
        energies[static_cast<std::size_t>(m)] = energy_of(static_cast<std::size_t>(m));
    for (double energy : energies)
        total += energy;
    return total;
}

} // namespace softgrain::dpm
