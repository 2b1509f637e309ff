// The least-squares fits every scene reports its slopes, moduli and exponents with (lib/core/fits.hpp),
// against closed forms: exact data give back their line, power law or slope to round-off; a three-point
// scatter gives the textbook estimates (slope S_xy/S_xx, its variance s^2/S_xx with s^2 = SSE/(n - 2));
// too few points give no fit. Tolerances: relative 1e-14 (some 50 eps) for sums of a few O(1) terms, 1e-13
// where logarithms enter.
#include "core/fits.hpp"
#include "support/tolerance.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace softgrain;
using softgrain::verification::Tolerance;

TEST_CASE("a line through exact data is that line, to round-off")
{
    const std::vector<double> x{-1.0, 0.5, 2.0, 3.5}, y{-1.0, 3.5, 8.0, 12.5}; // y = 2 + 3 x
    const auto line = fit_line(x, y);
    REQUIRE(line);
    CHECK_CLOSE(line->intercept, 2.0, (Tolerance{1e-14, 0}));
    CHECK_CLOSE(line->slope, 3.0, (Tolerance{1e-14, 0}));
    CHECK(line->slope_variance <= 1e-26); // squared round-off residuals, ~1e-30
    CHECK_CLOSE(fit_line_slope(x, y).value(), 3.0, (Tolerance{1e-14, 0}));
}

TEST_CASE("a scattered line: slope S_xy/S_xx and its variance s^2/S_xx")
{
    // x = 0, 1, 2, y = 0, 2, 1: S_xx = 2, S_xy = 1, slope 1/2, intercept 1/2, residuals -1/2, 1, -1/2,
    // SSE = 3/2, s^2 = SSE/(n - 2) = 3/2, variance of the slope s^2/S_xx = 3/4.
    const auto line = fit_line({0.0, 1.0, 2.0}, {0.0, 2.0, 1.0});
    REQUIRE(line);
    CHECK_CLOSE(line->slope, 0.5, (Tolerance{1e-14, 0}));
    CHECK_CLOSE(line->intercept, 0.5, (Tolerance{1e-14, 0}));
    CHECK_CLOSE(line->slope_variance, 0.75, (Tolerance{1e-14, 0}));
}

TEST_CASE("a power law's exponent and prefactor from its logarithms")
{
    std::vector<double> x, y;
    for (double v : {1e-3, 3e-3, 1e-2, 3e-2, 0.1}) {
        x.push_back(v);
        y.push_back(5.0 * std::pow(v, 1.5)); // Hertz's exponent
    }
    const auto law = fit_power_law(x, y);
    REQUIRE(law);
    CHECK_CLOSE(law->slope, 1.5, (Tolerance{1e-13, 0}));
    CHECK_CLOSE(std::exp(law->intercept), 5.0, (Tolerance{1e-13, 0}));
    CHECK_CLOSE(fit_power_law_exponent(x, y).value(), 1.5, (Tolerance{1e-13, 0}));
}

TEST_CASE("a slope through the origin is sum x y / sum x^2")
{
    // y = 4 x exactly, then scattered: x = 1, 2, y = 1, 3 gives (1 + 6)/(1 + 4) = 7/5.
    CHECK_CLOSE(fit_slope_through_origin({0.5, 1.0, 2.0}, {2.0, 4.0, 8.0}).value(), 4.0,
                (Tolerance{1e-14, 0}));
    CHECK_CLOSE(fit_slope_through_origin({1.0, 2.0}, {1.0, 3.0}).value(), 1.4, (Tolerance{1e-14, 0}));
}

TEST_CASE("too few points give no fit; a fit of unequal lengths is a defect")
{
    CHECK_FALSE(fit_line({1.0}, {2.0}));
    CHECK_FALSE(fit_line_slope({}, {}));
    CHECK_FALSE(fit_slope_through_origin({}, {}));
    CHECK_FALSE(fit_power_law({1.0, 2.0}, {1.0, 4.0}, 3)); // the minimum asked for
    CHECK(fit_power_law({1.0, 2.0}, {1.0, 4.0}));          // two points fit exactly
    CHECK_THROWS_AS(fit_line({1.0, 2.0}, {1.0}), std::logic_error);
}

TEST_CASE("an ensemble mean carries the sample standard deviation and the standard error of the mean")
{
    // 1, 2, 3, 4: mean 5/2, squared deviations 9/4 + 1/4 + 1/4 + 9/4 = 5 over n - 1 = 3, error sd / 2.
    const SampleMean four = sample_mean({1.0, 2.0, 3.0, 4.0});
    CHECK_CLOSE(four.mean, 2.5, (Tolerance{1e-15, 0}));
    CHECK_CLOSE(four.standard_deviation, std::sqrt(5.0 / 3.0), (Tolerance{1e-15, 0}));
    CHECK_CLOSE(four.standard_error, std::sqrt(5.0 / 3.0) / 2, (Tolerance{1e-15, 0}));
    // One sample is its own mean, exactly, and has no spread; none has no mean.
    const SampleMean one = sample_mean({0.8351});
    CHECK(one.mean == 0.8351);
    CHECK(std::isnan(one.standard_deviation));
    CHECK(std::isnan(one.standard_error));
    CHECK(std::isnan(sample_mean({}).mean));
}
