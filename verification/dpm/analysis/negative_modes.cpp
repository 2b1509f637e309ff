// Decision dpm-packing-minimum: a zero mode of the dynamical matrix (eq. 9.28, Figs. 9.14b, 9.15b) is an
// eigenvalue of magnitude below the zero threshold; one below minus the threshold is a negative mode (the
// packing is a saddle, not a minimum) and is counted apart, never as a zero mode. The 16 x 42 shell packing's
// "4th zero mode" was such a negative eigenvalue, lambda~ = -2.2e-8.
#include "dpm/analysis/modes.hpp"
#include "support/tolerance.hpp"

using namespace softgrain::dpm;

TEST_CASE("negative, zero and positive modes are counted apart [decision dpm-packing-minimum]")
{
    // Ascending: two below -threshold, three with |lambda| < threshold (one slightly negative), two above.
    const Eigen::VectorXd lambda =
        (Eigen::VectorXd(7) << -2e-8, -1e-9, -5e-11, 0.0, 3e-11, 2e-10, 1.0).finished();
    const SpectrumCounts counts = count_modes(lambda, 1e-10);
    CHECK(counts.negative == 2);
    CHECK(counts.zero == 3);
    CHECK(counts.first_positive() == 5);
    // A negative eigenvalue beyond the threshold is an instability, not a zero mode.
    CHECK(count_zero_modes(lambda, 1e-10) == 3);
    CHECK(count_negative_modes(lambda, 1e-10) == 2);
}
