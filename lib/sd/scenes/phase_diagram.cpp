// sd.phase_diagram: the regimes crossed by constant-kappa approaches and the Poiseuille-Hertz crossover
// (Rognon & Gay, Fig. 3b).
#include "core/fits.hpp"
#include "core/output.hpp"
#include "sd/approach_analysis.hpp"
#include "sd/scenes/parameters.hpp"
#include "sd/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace softgrain::sd {

namespace {

struct PhaseDiagramOptions
{
    double kappa_min = 1e-6, kappa_max = 0.3;
    int kappa_count = 12;
    double h0 = 100.0;
    double h_min = 1e-7;
    IntegratorChoice integrator;
};

OptionBinding<PhaseDiagramOptions> phase_diagram_binding()
{
    OptionBinding<PhaseDiagramOptions> binding;
    binding.real(&PhaseDiagramOptions::kappa_min, "kappa_min", "1", "smallest kappa (the paper: 1e-6)")
        .positive();
    binding.real(&PhaseDiagramOptions::kappa_max, "kappa_max", "1", "largest kappa (the paper: 0.3)")
        .positive()
        .at_most(1.0);
    binding.integer(&PhaseDiagramOptions::kappa_count, "kappa_count", "1", "log-spaced kappa values")
        .at_least(2);
    binding.real(&PhaseDiagramOptions::h0, "h0", "R", "initial gap (the paper: 100 R)").positive();
    binding.real(&PhaseDiagramOptions::h_min, "h_min", "R", "final gap").positive();
    bind_integrator(binding, &PhaseDiagramOptions::integrator);
    binding.check([](const PhaseDiagramOptions& options) {
        if (!(options.kappa_min < options.kappa_max))
            throw InputError("kappa_min = " + std::to_string(options.kappa_min) +
                             " must be below kappa_max = " + std::to_string(options.kappa_max));
    });
    return binding;
}

void run_phase_diagram(const PhaseDiagramOptions& options, RunContext& context)
{
    const double kappa_min = options.kappa_min, kappa_max = options.kappa_max;
    const int count = options.kappa_count;
    const double threshold = options.integrator.regime_width;
    const IntegratorSettings settings = adaptive_settings(options.integrator);

    auto& table = context.table(
        "phase_diagram.dat",
        {{"kappa", "1", "F_ext/(E R^2), eq. (6)"},
         {"h_start", "R", "initial gap"},
         {"h_end", "R", "final gap"},
         {"stokes_h_min", "R", "smallest h where w_Stokes <= regime_width (nan: none)"},
         {"stokes_h_max", "R", "largest such h"},
         {"poiseuille_h_min", "R", "smallest h where w_Poiseuille <= regime_width"},
         {"poiseuille_h_max", "R", "largest such h"},
         {"poiseuille_decades", "1", "log10(poiseuille_h_max/poiseuille_h_min), 0 if none"},
         {"hertz_h_min", "R", "smallest h where w_Hertz <= regime_width"},
         {"hertz_h_max", "R", "largest such h"},
         {"h_crossover", "R", "simulated h where delta = h"},
         {"kappa_crossover_exact", "1", "alpha sqrt 2 (h/R) sqrt(h-bar/R + h/R) at h_crossover"}});
    std::vector<double> log_h, log_kappa, decades;
    double relative_error_max = 0, kappa_vanishes = NAN, kappa_last_window = NAN;
    long total_steps = 0;
    auto progress = context.progress("sd.phase_diagram");
    for (long long i = 0; i < count; ++i) {
        const double kappa =
            kappa_min * std::pow(kappa_max / kappa_min, static_cast<double>(i) / (count - 1));
        const ApproachProblem problem = pair_problem(kappa, options.h0, options.h_min);
        const ApproachRun run = integrate_approach(problem, settings);
        total_steps += run.steps;
        const ApproachAnalysis analysis = analyse_approach(problem, run.samples, threshold);
        const std::optional<GapRange> ranges[3] = {
            regime_range(run.samples, Regime::stokes, 1.0, threshold),
            regime_range(run.samples, Regime::poiseuille, 1.0, threshold),
            regime_range(run.samples, Regime::hertz, 1.0, threshold)};
        const auto low = [&](int regime) { return ranges[regime] ? ranges[regime]->low : NAN; };
        const auto high = [&](int regime) { return ranges[regime] ? ranges[regime]->high : NAN; };
        const double window = ranges[1] ? ranges[1]->decades() : 0.0;
        decades.push_back(window);
        if (window == 0.0 && std::isnan(kappa_vanishes)) kappa_vanishes = kappa;
        if (window > 0.0) kappa_last_window = kappa;
        const double hc = analysis.h_crossover.value_or(NAN);
        const double kc = analysis.h_crossover ? crossover_kappa_paper(problem.material, hc) : NAN;
        if (analysis.h_crossover) {
            relative_error_max = std::max(relative_error_max, std::abs(kc / kappa - 1.0));
            if (hc <= 1e-2) { // the asymptotic branch kappa ~ (h/R)^(3/2) (h-bar = h within 1%)
                log_h.push_back(std::log(hc));
                log_kappa.push_back(std::log(kappa));
            }
        }
        table.row({kappa, run.samples.front().h, run.samples.back().h, low(0), high(0), low(1), high(1),
                   window, low(2), high(2), hc, kc});
        progress.update(static_cast<double>(i + 1) / static_cast<double>(count));
    }
    progress.finish();
    context.count_steps(total_steps);

    auto& lines = context.table("crossover_lines.dat",
                                {{"h", "R", "gap"},
                                 {"kappa_exact", "1", "delta = h: alpha sqrt2 (h/R) sqrt(h-bar/R + h/R)"},
                                 {"kappa_asymptotic", "1", "2 alpha (h/R)^(3/2)"}});
    const Material material;
    for (double h = 1e-7; h <= 1.0 + 1e-12; h *= std::pow(10.0, 0.1))
        lines.row({h, crossover_kappa_paper(material, h), crossover_kappa_asymptotic(material, h)});

    auto& summary = context.summary();
    summary["kappa_runs"] = count;
    summary["crossover_rel_error_max"] = relative_error_max;
    summary["crossover_points"] = log_h.size();
    if (const auto line = fit_line(log_h, log_kappa)) {
        summary["crossover_slope"] = line->slope;
        summary["crossover_prefactor"] = std::exp(line->intercept);
    } else {
        summary["crossover_slope"] = nullptr;
        summary["crossover_prefactor"] = nullptr;
    }
    summary["poiseuille_decades_at_kappa_min"] = decades.front();
    summary["kappa_poiseuille_vanishes"] = finite_or_null(kappa_vanishes);
    summary["kappa_poiseuille_last"] = finite_or_null(kappa_last_window);
    summary["poiseuille_window_nonincreasing"] = std::is_sorted(decades.rbegin(), decades.rend());
}

} // namespace

Scene phase_diagram_scene()
{
    return bound_scene(
               "sd.phase_diagram",
               "regimes crossed by constant-kappa approaches and the Poiseuille-Hertz crossover (SD Fig. 3b)",
               phase_diagram_binding(), run_phase_diagram)
        .without_vtk("a sweep of independent approaches over kappa, each ending at h = h_min: not a "
                     "time series; draw one approach with sd.approach --set kappa=K --vtk");
}

} // namespace softgrain::sd
