#include "sd/approach_analysis.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::sd {

double GapRange::decades() const
{
    return std::log10(high / low);
}

std::optional<GapRange> regime_range(const std::vector<ApproachSample>& samples, Regime regime, double radius,
                                     double width_threshold)
{
    std::optional<GapRange> range;
    for (const ApproachSample& s : samples)
        if (regime_width(regime, radius, s.h, s.rates.delta) <= width_threshold)
            range =
                range ? GapRange{std::min(range->low, s.h), std::max(range->high, s.h)} : GapRange{s.h, s.h};
    return range;
}

ApproachAnalysis analyse_approach(const ApproachProblem& p, const std::vector<ApproachSample>& samples,
                                  double width_threshold)
{
    const Material& m = p.material;
    const std::size_t n = samples.size();
    ApproachAnalysis out;
    out.exponents = local_exponents(samples);
    out.lambda1_exact.resize(n);
    out.lambda2_exact.resize(n);
    out.force_balance_residual.resize(n);
    out.deflection_residual.resize(n);
    out.time_reference.resize(n);
    out.h_error.resize(n);
    double t_ref = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const ApproachSample& s = samples[k];
        const double delta = s.rates.delta;
        out.lambda1_exact[k] = lambda1_paper(m, s.h, delta);
        out.lambda2_exact[k] = lambda2_paper(m, s.h, delta);
        out.force_balance_residual[k] = std::abs(s.rates.F_ela / s.F_ext - 1.0);
        out.deflection_residual[k] = std::abs(delta / balanced_deflection_paper(m, s.h, s.F_ext) - 1.0);
        if (k > 0) t_ref += approach_time_reference(p, samples[k - 1].h, s.h);
        out.time_reference[k] = t_ref;
        out.h_error[k] = std::abs(s.rates.h_dot) * std::abs(s.t - t_ref) / s.h;
    }
    const auto best = [&](Regime regime) -> std::optional<RegimePoint> {
        std::optional<RegimePoint> found;
        for (std::size_t k = 1; k + 1 < n; ++k) { // interior samples: centred exponents
            const double w = regime_width(regime, m.radius, samples[k].h, samples[k].rates.delta);
            if (w <= width_threshold && (!found || w < found->width))
                found = RegimePoint{k, samples[k].h, w, out.exponents.lambda1[k], out.exponents.lambda2[k]};
        }
        return found;
    };
    out.stokes = best(Regime::stokes);
    out.poiseuille = best(Regime::poiseuille);
    out.hertz = best(Regime::hertz);
    for (std::size_t k = 1; k < n; ++k) {
        const double before = std::log(samples[k - 1].rates.delta / samples[k - 1].h);
        const double after = std::log(samples[k].rates.delta / samples[k].h);
        if (before < 0 && after >= 0) {
            const double f = before / (before - after);
            out.h_crossover = std::exp(std::log(samples[k - 1].h) +
                                       f * (std::log(samples[k].h) - std::log(samples[k - 1].h)));
            break;
        }
    }
    for (std::size_t k = 1; k + 1 < n; ++k) {
        out.lambda_error_max =
            std::max(out.lambda_error_max, std::abs(out.exponents.lambda1[k] - out.lambda1_exact[k]));
        out.lambda_error_max =
            std::max(out.lambda_error_max, std::abs(out.exponents.lambda2[k] - out.lambda2_exact[k]));
    }
    return out;
}

ApproachMaxima approach_maxima(const ApproachProblem& problem, const std::vector<ApproachSample>& samples,
                               const ApproachAnalysis& analysis, double width_threshold)
{
    const double radius = problem.material.radius;
    ApproachMaxima maxima;
    double hertz_error = -1; // none yet
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const ApproachSample& sample = samples[k];
        maxima.modes.push_back(jacobian_modes(problem, sample.t, sample.X, sample.h));
        maxima.stiffness_max = std::max(maxima.stiffness_max, -maxima.modes.back().fast);
        if (regime_width(Regime::hertz, radius, sample.h, sample.rates.delta) <= width_threshold)
            hertz_error = std::max(hertz_error, analysis.h_error[k]);
    }
    maxima.force_balance_residual_max =
        *std::max_element(analysis.force_balance_residual.begin(), analysis.force_balance_residual.end());
    maxima.deflection_residual_max =
        *std::max_element(analysis.deflection_residual.begin(), analysis.deflection_residual.end());
    maxima.h_error_max = *std::max_element(analysis.h_error.begin(), analysis.h_error.end());
    if (hertz_error >= 0) maxima.h_error_hertz = hertz_error;
    return maxima;
}

double gap_rate_derivative_max(const ApproachProblem& problem)
{
    double rate_max = 0;
    for (double h = problem.h0; h >= problem.h_min; h /= std::pow(10.0, 0.05))
        rate_max = std::max(rate_max, std::abs(gap_rate_derivative(problem, h, 0.0)));
    return rate_max;
}

} // namespace softgrain::sd
