// Checks of a 3D packing at the end of the jamming protocol (DPM sec. 9.4), shared by the rough and smooth
// jamming tests: 1 <= P/P_t < 1.01; FIRE's stopping rule (rms force below its tolerance); every particle in
// contact; after Newton polishing to round-off forces (a residual force f shifts the zero modes by ~f R), the
// dynamical matrix (eq. 9.28) has exactly the 3 zero modes of the periodic translations plus 6 per rattler
// (sec. 9.4.3, Fig. 9.15b). The smallest non-zero eigenvalue is ~1e-4 k_v v0^(4/3), the zero ones ~1e-16,
// threshold 1e-10 (Fig. 9.15a).
#pragma once

#include "dpm/jam3d.hpp"
#include "dpm/modes.hpp"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace softgrain::verification {

inline void check_jammed3d(dpm::Jam3dResult& j, double pressure_onset)
{
    using namespace softgrain::dpm;
    CHECK(j.pressure >= pressure_onset);
    CHECK(j.pressure < 1.01 * pressure_onset);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(j.x.size());
    total_energy3d(j.system, j.x, &g, nullptr);
    CHECK(g.norm() / std::sqrt(double(g.size())) < j.fire.force_tolerance); // FIRE's stopping rule
    for (int c : contact_counts3d(j.system, j.x))
        CHECK(c > 0);
    const EnergyWithDerivatives energy = [&j](const Eigen::VectorXd& y, Eigen::VectorXd* gr,
                                              Eigen::MatrixXd* h) {
        return total_energy3d(j.system, y, gr, h);
    };
    polish_newton(energy, j.x, 1e-14 * j.pressure_unit, 30);
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
    total_energy3d(j.system, j.x, nullptr, &m);
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues() /
        j.eigenvalue_unit;
    const std::vector<int> after = contact_counts3d(j.system, j.x);
    const auto rattlers = std::count(after.begin(), after.end(), 0);
    CHECK(count_zero_modes(lambda, 1e-10) == 3 + 6 * rattlers);
    MESSAGE("phi = " << j.phi << ", box steps " << j.box_steps << ", FIRE iterations " << j.fire_iterations
                     << ", rattlers " << rattlers);
}

} // namespace softgrain::verification
