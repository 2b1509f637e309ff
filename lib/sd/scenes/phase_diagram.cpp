// sd.phase_diagram: the regimes crossed by constant-kappa approaches and the Poiseuille-Hertz crossover
// (Rognon & Gay, Fig. 3b): the approaches and their reductions (sd/phase_diagram.hpp), then the table, the
// paper's crossover lines and the summary.
#include "sd/phase_diagram.hpp"
#include "core/output.hpp"
#include "sd/scaling.hpp"
#include "sd/scenes/parameters.hpp"
#include "sd/scenes/scenes.hpp"

#include <cmath>
#include <optional>
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

// The approaches at the scene's kappas (phase_diagram), with progress on stderr.
PhaseDiagram run_approaches(const PhaseDiagramOptions& options, RunContext& context)
{
    PhaseDiagramSetup setup;
    setup.pair = pair_problem(options.kappa_min, options.h0, options.h_min); // each kappa's loading in turn
    setup.kappa_min = options.kappa_min;
    setup.kappa_max = options.kappa_max;
    setup.kappa_count = options.kappa_count;
    setup.settings = adaptive_settings(options.integrator);
    setup.regime_width = options.integrator.regime_width;
    auto progress = context.progress("sd.phase_diagram");
    PhaseDiagram diagram = phase_diagram(setup, [&progress](double fraction) { progress.update(fraction); });
    progress.finish();
    return diagram;
}

void write_phase_diagram_table(const PhaseDiagram& diagram, RunContext& context)
{
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
    const auto low = [](const std::optional<GapRange>& range) { return range ? range->low : NAN; };
    const auto high = [](const std::optional<GapRange>& range) { return range ? range->high : NAN; };
    for (const PhaseDiagramPoint& point : diagram.points)
        table.row({point.kappa, point.h_start, point.h_end, low(point.stokes), high(point.stokes),
                   low(point.poiseuille), high(point.poiseuille), point.poiseuille_decades(),
                   low(point.hertz), high(point.hertz), point.h_crossover.value_or(NAN),
                   point.kappa_crossover_exact});
}

void run_phase_diagram(const PhaseDiagramOptions& options, RunContext& context)
{
    const PhaseDiagram diagram = run_approaches(options, context);
    context.count_steps(diagram.steps);
    write_phase_diagram_table(diagram, context);

    auto& lines = context.table("crossover_lines.dat",
                                {{"h", "R", "gap"},
                                 {"kappa_exact", "1", "delta = h: alpha sqrt2 (h/R) sqrt(h-bar/R + h/R)"},
                                 {"kappa_asymptotic", "1", "2 alpha (h/R)^(3/2)"}});
    const Material material;
    for (double h = 1e-7; h <= 1.0 + 1e-12; h *= std::pow(10.0, 0.1))
        lines.row({h, crossover_kappa_paper(material, h), crossover_kappa_asymptotic(material, h)});

    auto& summary = context.summary();
    summary["kappa_runs"] = options.kappa_count;
    summary["crossover_rel_error_max"] = diagram.crossover_relative_error_max;
    summary["crossover_points"] = diagram.crossover_points;
    if (const auto& line = diagram.crossover_line) {
        summary["crossover_slope"] = line->slope;
        summary["crossover_prefactor"] = std::exp(line->intercept);
    } else {
        summary["crossover_slope"] = nullptr;
        summary["crossover_prefactor"] = nullptr;
    }
    summary["poiseuille_decades_at_kappa_min"] = diagram.points.front().poiseuille_decades();
    summary["kappa_poiseuille_vanishes"] = value_or_null(diagram.kappa_poiseuille_vanishes);
    summary["kappa_poiseuille_last"] = value_or_null(diagram.kappa_poiseuille_last);
    summary["poiseuille_window_nonincreasing"] = diagram.poiseuille_window_nonincreasing;
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
