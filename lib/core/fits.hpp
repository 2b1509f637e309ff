// Least-squares fits of measured curves (GSL, gsl_fit_linear and gsl_fit_mul): the slopes, moduli and
// power-law exponents that scenes report in their summaries. One place for them, so that every scene fits
// the same way and states the same minimum of points. x and y have the same length; a fit over fewer points
// than it needs is absent (the scene writes null), never a number made up from too little data.
#pragma once

#include <limits>
#include <optional>
#include <vector>

namespace softgrain {

// y = intercept + slope x, by ordinary least squares: absent below two points. slope_variance is the
// variance of the slope estimated from the scatter about the line (gsl_fit_linear's cov11; NaN for two
// points, which leave no scatter).
struct Line
{
    double intercept = 0, slope = 0, slope_variance = 0;
};
std::optional<Line> fit_line(const std::vector<double>& x, const std::vector<double>& y);
// Its slope alone.
std::optional<double> fit_line_slope(const std::vector<double>& x, const std::vector<double>& y);

// y = slope x (a line through the origin, e.g. a modulus from stress against strain): absent without a point.
std::optional<double> fit_slope_through_origin(const std::vector<double>& x, const std::vector<double>& y);

// y = a x^b as the least-squares line ln y = ln a + b ln x (every x, y > 0): slope b, intercept ln a;
// absent below `minimum_points` (at least two).
std::optional<Line> fit_power_law(const std::vector<double>& x, const std::vector<double>& y,
                                  std::size_t minimum_points = 2);
// Its exponent b alone.
std::optional<double> fit_power_law_exponent(const std::vector<double>& x, const std::vector<double>& y,
                                             std::size_t minimum_points = 2);

// The mean of independent samples (e.g. the packings of an ensemble), the least-squares fit of a constant, with
// the sample standard deviation (n - 1 in the denominator, gsl_stats_sd) and the standard error of the mean,
// sd / sqrt(n). Below two samples the spread is unknown: both are NaN (the scene writes null); without a
// sample the mean is NaN too.
struct SampleMean
{
    double mean = std::numeric_limits<double>::quiet_NaN();
    double standard_deviation = std::numeric_limits<double>::quiet_NaN();
    double standard_error = std::numeric_limits<double>::quiet_NaN();
};
SampleMean sample_mean(const std::vector<double>& samples);

} // namespace softgrain
