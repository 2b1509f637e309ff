// What a simulated approach says about the paper's claims: local exponents per regime, the Poiseuille-Hertz
// crossover, the consistency of eqs. (1) and (2), and the error of h(t) against the quadrature reference.
// Shared by the scenes sd.approach and sd.phase_diagram and by verification/sd.
#pragma once

#include "sd/approach.hpp"
#include "sd/scaling.hpp"

#include <optional>
#include <vector>

namespace softgrain::sd {

// The sample of a regime where its width w (scaling.hpp) is smallest, and the exponents measured there.
struct RegimePoint
{
    std::size_t index = 0;
    double h = 0, width = 0, lambda1 = 0, lambda2 = 0;
};

struct ApproachAnalysis
{
    LocalExponents exponents;
    std::vector<double> lambda1_exact, lambda2_exact; // scaling.hpp formulas at each sample's (h, delta)
    std::vector<double> force_balance_residual;       // |F_ela/F_ext - 1| (eq. 1)
    std::vector<double> deflection_residual; // |delta(eq. 2) / delta_eq(h) - 1|, delta_eq from eq. (1)
    std::vector<double> time_reference;      // t(h) by quadrature (constant loading)
    std::vector<double> h_error;             // |h-dot| |t - t_ref(h)| / h: relative error of h(t)
    // Empty when the narrowest width exceeds the threshold.
    std::optional<RegimePoint> stokes, poiseuille, hertz;
    std::optional<double> h_crossover; // where delta = h (interpolated in ln h)
    double lambda_error_max = 0;       // max |lambda_sim - lambda_exact| over interior samples
};

// The range [h_low, h_high] of the samples where a regime's width is at most width_threshold; empty if none.
struct GapRange
{
    double low, high;
    double decades() const;
};
std::optional<GapRange> regime_range(const std::vector<ApproachSample>& samples, Regime regime, double radius,
                                     double width_threshold);

// Requires the paper's laws and constant loading (the reference quadrature and the exact exponents assume
// them).
ApproachAnalysis analyse_approach(const ApproachProblem& problem, const std::vector<ApproachSample>& samples,
                                  double width_threshold);

// The stiffness of eqs. (7), (9) along a simulated approach and the largest residuals and errors of its
// analysis (sd.approach).
struct ApproachMaxima
{
    std::vector<ModeRates> modes;          // jacobian_modes at each sample (approach.hpp)
    double stiffness_max = 0;              // max over the samples of -modes.fast, at least 0
    double force_balance_residual_max = 0; // of the analysis's per-sample values
    double deflection_residual_max = 0;
    double h_error_max = 0;
    // The largest h_error over the samples in the Hertz regime (width at most width_threshold); empty if none.
    std::optional<double> h_error_hertz;
};
ApproachMaxima approach_maxima(const ApproachProblem& problem, const std::vector<ApproachSample>& samples,
                               const ApproachAnalysis& analysis, double width_threshold);

// The fastest rate of the balanced dynamics along the path, max |d h-dot/dh| (gap_rate_derivative, at
// t = 0) over h from h0 down to h_min in steps of 0.05 decades (1/s).
double gap_rate_derivative_max(const ApproachProblem& problem);

} // namespace softgrain::sd
