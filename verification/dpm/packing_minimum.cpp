// Decision dpm-packing-minimum: the spectrum of a packing (eq. 9.28, Figs. 9.14b, 9.15b) is taken at a
// minimum of its energy. FIRE stops on the force alone and can stop on or beside a saddle, where the Newton
// polish (which steps along the positive modes only) cannot leave; a negative eigenvalue is then neither a
// zero mode nor part of a stable packing's spectrum. settle_at_minimum leaves such a saddle along its
// negative mode; count_modes keeps negative and zero modes apart.
#include "core/fire.hpp"
#include "dpm/modes.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// U = (x^2 - 1)^2 + y^2 / 2: a saddle at the origin (eigenvalues -4 and 1), minima at x = +-1 (8 and 1).
double double_well(const Eigen::VectorXd& r, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian)
{
    const double x = r(0), y = r(1);
    if (gradient) *gradient += Eigen::Vector2d(4 * x * (x * x - 1), y);
    if (hessian) *hessian += Eigen::Vector2d(12 * x * x - 4, 1).asDiagonal().toDenseMatrix();
    return (x * x - 1) * (x * x - 1) + 0.5 * y * y;
}

void relax_double_well(Eigen::VectorXd& r)
{
    FireOptions options;
    options.dt_max = 0.05;
    options.force_tolerance = 1e-12;
    fire_minimise(
        r,
        [](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
            f = Eigen::VectorXd::Zero(y.size());
            const double u = double_well(y, &f, nullptr);
            f = -f;
            return u;
        },
        options);
}

} // namespace

TEST_CASE("a packing stopped on a saddle is moved to the minimum before its spectrum is taken "
          "[decision dpm-packing-minimum]")
{
    // Exactly on the saddle: zero force, so FIRE and the Newton polish stay there.
    Eigen::VectorXd r = Eigen::Vector2d(0.0, 0.3);
    const MinimumSettling settled = settle_at_minimum(double_well, relax_double_well, r, 1.0, 1.0, 1e-10);
    CHECK(settled.saddle_escapes == 1);
    // At a minimum x = +-1, y = 0 (to the polish's force 1e-14 over the curvatures 8 and 1)...
    CHECK_CLOSE(std::abs(r(0)), 1.0, (Tolerance{0, 1e-14}));
    CHECK_CLOSE(r(1), 0.0, (Tolerance{0, 1e-14}));
    // ... whose lowest eigenvalue is the y curvature, 1.
    CHECK_CLOSE(settled.lowest_eigenvalue, 1.0, (Tolerance{1e-12, 0}));
    CHECK(settled.force_max < 1e-14);

    // At a minimum already: nothing to escape.
    const MinimumSettling again = settle_at_minimum(double_well, relax_double_well, r, 1.0, 1.0, 1e-10);
    CHECK(again.saddle_escapes == 0);
}

TEST_CASE("negative, zero and positive modes are counted apart")
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
}
