// DPM eq. (9.28), Fig. 9.5(a): the dynamical matrix of a compressed triangular (hexagonal) crystal of soft
// disks against the exact phonon spectrum of the lattice (dpm/system/crystal.hpp): all 2 n^2 eigenvalues.
#include "dpm/analysis/modes.hpp"
#include "dpm/system/crystal.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

TEST_CASE("triangular soft-disk crystal: the dynamical matrix has the exact phonon spectrum [DPM eq. (9.28), "
          "Fig. 9.5(a)]")
{
    const double sigma = 1.0, k = 1.0;
    for (double a : {0.999, 0.99}) { // compressions 1e-3 and 1e-2 sigma: the tension term matters at 1e-2
        CAPTURE(a);
        const int n = 6;
        Eigen::VectorXd x;
        const DpmSystem s = triangular_crystal(n, a, sigma, k, x);
        const Eigen::VectorXd lambda = vibrational_modes(s, x).eigenvalues;
        const std::vector<Phonon> exact = phonon_spectrum(n, a, sigma, k);
        REQUIRE(lambda.size() == static_cast<Eigen::Index>(exact.size()));
        // Dense eigensolver round-off: a few ulp of the largest eigenvalue (about 6 k).
        for (std::size_t m = 0; m < exact.size(); ++m)
            CHECK_CLOSE(lambda(static_cast<Eigen::Index>(m)), exact[m].lambda, (Tolerance{0, 1e-12}));
        // The two translations are the only zero modes; the lowest phonon is at |q| = 2 pi/(n a).
        CHECK(std::abs(exact[1].lambda) < 1e-14);
        CHECK(exact[2].lambda > 1e-2);
    }
}
