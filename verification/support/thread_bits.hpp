// Support of the tests that a parallel sum gives the same bits for every OpenMP thread count (the DPM shape
// energies summed over particles, dpm/system/particle_sum.hpp): an energy and its gradient computed on 1 and
// 2 threads, checked against each other and against the serial loop.
#pragma once

#include <doctest/doctest.h>
#include <omp.h>

#include <Eigen/Core>
#include <array>

namespace softgrain::verification {

struct EnergyAndGradient
{
    double energy = 0;
    Eigen::VectorXd gradient;
};

// energy_of(gradient): the energy, adding its gradient to the zeroed vector of `size`; evaluated with 1 and
// then 2 OpenMP threads, the thread count restored afterwards.
template <class EnergyOf>
std::array<EnergyAndGradient, 2> on_one_and_two_threads(Eigen::Index size, const EnergyOf& energy_of)
{
    const int threads_before = omp_get_max_threads();
    std::array<EnergyAndGradient, 2> results;
    for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        EnergyAndGradient& r = results[threads - 1];
        r.gradient = Eigen::VectorXd::Zero(size);
        r.energy = energy_of(r.gradient);
    }
    omp_set_num_threads(threads_before);
    return results;
}

// The same bits on 1 and 2 threads and from the serial loop; a non-zero gradient, so that the comparison
// says something.
inline void check_same_bits(const std::array<EnergyAndGradient, 2>& threaded, const EnergyAndGradient& serial)
{
    CHECK(threaded[0].energy == threaded[1].energy);
    CHECK(threaded[0].gradient == threaded[1].gradient);
    CHECK(threaded[1].energy == serial.energy);
    CHECK(threaded[1].gradient == serial.gradient);
    REQUIRE(threaded[0].gradient.norm() > 0);
}

} // namespace softgrain::verification
