// Seeded random numbers: reproducible per seed, and with the moments of their distributions.
#include "core/rng.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using softgrain::verification::Tolerance;

TEST_CASE("the same seed gives the same stream; another seed another")
{
    Rng a(42), b(42), c(43);
    bool all_equal = true, any_differs = false;
    for (int i = 0; i < 100; ++i) {
        const double x = a.uniform(), y = b.uniform(), z = c.uniform();
        all_equal = all_equal && x == y;
        any_differs = any_differs || x != z;
    }
    CHECK(all_equal);
    CHECK(any_differs);
}

TEST_CASE("uniform and normal samples have the right mean and variance (within 4 standard errors)")
{
    Rng rng(7);
    const int n = 200000;
    double sum_u = 0, sum_u2 = 0, sum_g = 0, sum_g2 = 0;
    for (int i = 0; i < n; ++i) {
        const double u = rng.uniform(), g = rng.normal(2.0);
        sum_u += u;
        sum_u2 += u * u;
        sum_g += g;
        sum_g2 += g * g;
    }
    // Standard errors of the sample mean: sqrt(var/n); of the second moment: sqrt(var(x^2)/n).
    CHECK_CLOSE(sum_u / n, 0.5, (Tolerance{0, 4 * std::sqrt(1.0 / 12 / n)}));
    CHECK_CLOSE(sum_u2 / n, 1.0 / 3, (Tolerance{0, 4 * std::sqrt((1.0 / 5 - 1.0 / 9) / n)}));
    CHECK_CLOSE(sum_g / n, 0.0, (Tolerance{0, 4 * std::sqrt(4.0 / n)}));
    CHECK_CLOSE(sum_g2 / n, 4.0, (Tolerance{0, 4 * std::sqrt(2.0 * 16.0 / n)}));
}
