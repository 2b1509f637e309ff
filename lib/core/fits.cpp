#include "core/fits.hpp"

#include <gsl/gsl_fit.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace softgrain {

namespace {

void require_pairs(const std::vector<double>& x, const std::vector<double>& y)
{
    if (x.size() != y.size())
        throw std::logic_error("a least-squares fit was given " + std::to_string(x.size()) +
                               " abscissae and " + std::to_string(y.size()) + " ordinates");
}

} // namespace

std::optional<Line> fit_line(const std::vector<double>& x, const std::vector<double>& y)
{
    require_pairs(x, y);
    if (x.size() < 2) return std::nullopt;
    Line line;
    double cov00 = 0, cov01 = 0, sum_squares = 0;
    gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &line.intercept, &line.slope, &cov00, &cov01,
                   &line.slope_variance, &sum_squares);
    return line;
}

std::optional<double> fit_line_slope(const std::vector<double>& x, const std::vector<double>& y)
{
    const auto line = fit_line(x, y);
    return line ? std::optional<double>(line->slope) : std::nullopt;
}

std::optional<double> fit_slope_through_origin(const std::vector<double>& x, const std::vector<double>& y)
{
    require_pairs(x, y);
    if (x.empty()) return std::nullopt;
    double slope = 0, variance = 0, sum_squares = 0;
    gsl_fit_mul(x.data(), 1, y.data(), 1, x.size(), &slope, &variance, &sum_squares);
    return slope;
}

std::optional<Line> fit_power_law(const std::vector<double>& x, const std::vector<double>& y,
                                  std::size_t minimum_points)
{
    require_pairs(x, y);
    if (x.size() < std::max<std::size_t>(2, minimum_points)) return std::nullopt;
    std::vector<double> log_x(x.size()), log_y(y.size());
    std::transform(x.begin(), x.end(), log_x.begin(), [](double v) { return std::log(v); });
    std::transform(y.begin(), y.end(), log_y.begin(), [](double v) { return std::log(v); });
    return fit_line(log_x, log_y);
}

std::optional<double> fit_power_law_exponent(const std::vector<double>& x, const std::vector<double>& y,
                                             std::size_t minimum_points)
{
    const auto line = fit_power_law(x, y, minimum_points);
    return line ? std::optional<double>(line->slope) : std::nullopt;
}

SampleMean sample_mean(const std::vector<double>& samples)
{
    SampleMean result;
    if (samples.empty()) return result;
    result.mean = gsl_stats_mean(samples.data(), 1, samples.size());
    if (samples.size() < 2) return result;
    result.standard_deviation = gsl_stats_sd_m(samples.data(), 1, samples.size(), result.mean);
    result.standard_error = result.standard_deviation / std::sqrt(static_cast<double>(samples.size()));
    return result;
}

} // namespace softgrain
