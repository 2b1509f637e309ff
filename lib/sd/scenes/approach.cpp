// sd.approach: two lubricated elastic spheres under a constant force (Rognon & Gay, Fig. 3): delta(h),
// h-dot(h), the local exponents per regime and the Poiseuille-Hertz crossover.
#include "core/output.hpp"
#include "sd/approach_analysis.hpp"
#include "sd/scenes/parameters.hpp"
#include "sd/scenes/scenes.hpp"
#include "sd/vtk_frames.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

namespace softgrain::sd {

namespace {

struct ApproachOptions
{
    double kappa = 1e-6;
    double h0 = 100.0;
    double h_min = 1e-6;
    bool fixed_step = false;
    double dt = 1.0; // [R/V]
    int max_steps = 50'000'000;
    int timing_repeats = 1;
    IntegratorChoice integrator;
};

OptionBinding<ApproachOptions> approach_binding()
{
    OptionBinding<ApproachOptions> binding;
    binding.real(&ApproachOptions::kappa, "kappa", "1", "renormalised force F_ext/(E R^2), eq. (6)")
        .positive()
        .at_most(1.0);
    binding.real(&ApproachOptions::h0, "h0", "R", "initial gap (the paper: 100 R)").positive();
    binding.real(&ApproachOptions::h_min, "h_min", "R", "the run stops when h reaches h_min").positive();
    binding.choice(&ApproachOptions::fixed_step, "step_control", {{"adaptive", false}, {"fixed", true}},
                   "adaptive error control, or a fixed step dt (stability study)");
    binding.real(&ApproachOptions::dt, "dt", "R/V", "fixed step (step_control = fixed)").positive();
    binding.integer(&ApproachOptions::max_steps, "max_steps", "1", "guard against a stalled run").at_least(1);
    binding
        .integer(&ApproachOptions::timing_repeats, "timing_repeats", "1",
                 "integrations timed (best of); results are identical")
        .at_least(1);
    bind_integrator(binding, &ApproachOptions::integrator);
    return binding;
}

// One approach at the scene's options: the integration (timed), its analysis and the maxima the summary
// reports.
struct ApproachOutcome
{
    ApproachProblem problem;
    IntegratorSettings settings;
    ApproachRun run;
    double seconds = INFINITY; // wall time of the integration alone, best of timing_repeats
    ApproachAnalysis analysis;
    ApproachMaxima maxima;
};

ApproachOutcome approach(const ApproachOptions& options)
{
    ApproachOutcome outcome;
    outcome.problem = pair_problem(options.kappa, options.h0, options.h_min);
    outcome.settings = adaptive_settings(options.integrator);
    outcome.settings.fixed_step = options.fixed_step;
    outcome.settings.dt = options.dt / options.kappa; // R/V = eta R^2 / F = 1/kappa in scene units
    outcome.settings.max_steps = options.max_steps;
    // The runs being identical, the last one is kept.
    for (int repeat = 0; repeat < options.timing_repeats; ++repeat) {
        const auto start = std::chrono::steady_clock::now();
        outcome.run = integrate_approach(outcome.problem, outcome.settings);
        outcome.seconds = std::min(outcome.seconds, seconds_since(start));
    }
    const double width = options.integrator.regime_width;
    outcome.analysis = analyse_approach(outcome.problem, outcome.run.samples, width);
    outcome.maxima = approach_maxima(outcome.problem, outcome.run.samples, outcome.analysis, width);
    return outcome;
}

// ParaView frames, one per row of approach.dat (--vtk-every N: every N-th), time value t in R/V as there: the
// two spheres and their pair, field data time t [s] and gap_min h [m].
void write_approach_frames(const ApproachOutcome& outcome, double kappa, RunContext& context)
{
    auto* series = context.vtk();
    if (!series) return;
    for (const ApproachSample& sample : outcome.run.samples) {
        if (!series->next()) continue;
        std::vector<vtk::Part> parts = approach_frame(outcome.problem, sample);
        for (auto& part : parts) {
            part.data.field("time", sample.t);
            part.data.field("gap_min", sample.h);
        }
        series->write(sample.t * kappa, parts);
    }
}

void write_approach_table(const ApproachOutcome& outcome, double kappa, RunContext& context)
{
    auto& table = context.table(
        "approach.dat",
        {{"t", "R/V", "time"},
         {"X", "R", "centre distance X"},
         {"h", "R", "gap h"},
         {"delta", "R", "deflection delta from eq. (2)"},
         {"a", "R", "interaction size a, eq. (5)"},
         {"h_dot", "V", "gap rate, eq. (7)"},
         {"X_dot", "V", "centre rate, eq. (9)"},
         {"lambda1", "1", "local exponent d ln delta/d ln h (3-point difference)"},
         {"lambda2", "1", "local exponent d ln|h-dot|/d ln h (3-point difference)"},
         {"lambda1_exact", "1", "exact exponent for eqs. (3)-(5) at (h, delta)"},
         {"lambda2_exact", "1", "exact exponent for eqs. (3)-(5) at (h, delta)"},
         {"force_balance_residual", "1", "|F_ela/F_ext - 1|, eq. (1)"},
         {"deflection_residual", "1", "|delta(eq. 2)/delta_eq(h) - 1|, delta_eq from eq. (1)"},
         {"h_error", "1", "relative error of h(t) against the quadrature t(h)"},
         {"width_stokes", "1", "(R/h)(3 - 2R/(R + delta))"},
         {"width_poiseuille", "1", "h/R + 3 delta/h"},
         {"width_hertz", "1", "3h/R + 4h/(3 delta)"},
         {"mode_fast", "1", "most negative Re eigenvalue of d(X-dot, h-dot)/d(X, h), times h/|h-dot|"},
         {"mode_slow", "1", "the other Re eigenvalue, times h/|h-dot|"}});
    const double R = outcome.problem.material.radius;
    const ApproachAnalysis& analysis = outcome.analysis;
    for (std::size_t k = 0; k < outcome.run.samples.size(); ++k) {
        const ApproachSample& sample = outcome.run.samples[k];
        const PairRates& rates = sample.rates;
        const ModeRates& modes = outcome.maxima.modes[k];
        table.row({sample.t * kappa, sample.X, sample.h, rates.delta, rates.a, rates.h_dot / kappa,
                   rates.X_dot / kappa, analysis.exponents.lambda1[k], analysis.exponents.lambda2[k],
                   analysis.lambda1_exact[k], analysis.lambda2_exact[k], analysis.force_balance_residual[k],
                   analysis.deflection_residual[k], analysis.h_error[k],
                   regime_width(Regime::stokes, R, sample.h, rates.delta),
                   regime_width(Regime::poiseuille, R, sample.h, rates.delta),
                   regime_width(Regime::hertz, R, sample.h, rates.delta), modes.fast, modes.slow});
    }
}

void write_approach_summary(const ApproachOutcome& outcome, double kappa, RunContext& context)
{
    const ApproachAnalysis& analysis = outcome.analysis;
    const ApproachMaxima& maxima = outcome.maxima;
    const Material& material = outcome.problem.material;
    auto& summary = context.summary();
    const auto regime = [&](const std::string& name, const std::optional<RegimePoint>& point) {
        summary["lambda1_" + name] = point ? nlohmann::json(point->lambda1) : nlohmann::json(nullptr);
        summary["lambda2_" + name] = point ? nlohmann::json(point->lambda2) : nlohmann::json(nullptr);
        summary["h_" + name] = point ? nlohmann::json(point->h) : nlohmann::json(nullptr);
        summary["width_" + name] = point ? nlohmann::json(point->width) : nlohmann::json(nullptr);
    };
    regime("stokes", analysis.stokes);
    regime("poiseuille", analysis.poiseuille);
    regime("hertz", analysis.hertz);
    const ApproachSample& first = outcome.run.samples.front();
    const ApproachSample& last = outcome.run.samples.back();
    summary["h_crossover"] = value_or_null(analysis.h_crossover);
    summary["kappa_crossover_exact"] =
        analysis.h_crossover ? nlohmann::json(crossover_kappa_paper(material, *analysis.h_crossover))
                             : nlohmann::json(nullptr);
    summary["kappa_crossover_asymptotic"] =
        analysis.h_crossover ? nlohmann::json(crossover_kappa_asymptotic(material, *analysis.h_crossover))
                             : nlohmann::json(nullptr);
    summary["lambda_error_max"] = analysis.lambda_error_max;
    summary["force_balance_residual_max"] = maxima.force_balance_residual_max;
    summary["deflection_residual_max"] = maxima.deflection_residual_max;
    summary["h_error_max"] = maxima.h_error_max;
    summary["h_error_hertz"] = value_or_null(maxima.h_error_hertz);
    summary["stiffness_max"] = maxima.stiffness_max;
    summary["h_final"] = last.h;
    summary["t_final"] = last.t * kappa;
    summary["delta_start"] = first.rates.delta;
    summary["delta_end"] = last.rates.delta;
    summary["a_end"] = last.rates.a;
    summary["h_dot_start"] = first.rates.h_dot / kappa;
    summary["samples"] = outcome.run.samples.size();
    summary["steps"] = outcome.run.steps;
    summary["rhs_evaluations"] = outcome.run.rhs_evaluations;
    summary["integration_wall_time_s"] = outcome.seconds;
    const Stepper& stepper = find_stepper(outcome.settings.stepper);
    summary["stepper_index"] = stepper.index;
    summary["stepper_implicit"] = stepper.implicit;
    summary["dt_lambda_max"] =
        outcome.settings.fixed_step ? nlohmann::json(outcome.run.dt_lambda_max) : nlohmann::json(nullptr);
    // In V/R: the rate of the problem (1/s, R = eta = 1) over kappa.
    summary["gap_rate_derivative_max"] = gap_rate_derivative_max(outcome.problem) / kappa;
}

void run_approach(const ApproachOptions& options, RunContext& context)
{
    const ApproachOutcome outcome = approach(options);
    context.count_steps(outcome.run.steps);
    write_approach_frames(outcome, options.kappa, context);
    write_approach_table(outcome, options.kappa, context);
    write_approach_summary(outcome, options.kappa, context);
}

} // namespace

Scene approach_scene()
{
    return bound_scene("sd.approach",
                       "two lubricated elastic spheres under constant force: delta(h), h-dot(h), local "
                       "exponents (SD Fig. 3)",
                       approach_binding(), run_approach)
        .with_vtk();
}

} // namespace softgrain::sd
