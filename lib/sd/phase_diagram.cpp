#include "sd/phase_diagram.hpp"

#include "sd/scaling.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::sd {

double PhaseDiagramPoint::poiseuille_decades() const
{
    return poiseuille ? poiseuille->decades() : 0.0;
}

namespace {

PhaseDiagramPoint phase_diagram_point(const ApproachProblem& problem, const ApproachRun& run, double kappa,
                                      double regime_width)
{
    const ApproachAnalysis analysis = analyse_approach(problem, run.samples, regime_width);
    PhaseDiagramPoint point;
    point.kappa = kappa;
    point.h_start = run.samples.front().h;
    point.h_end = run.samples.back().h;
    point.stokes = regime_range(run.samples, Regime::stokes, 1.0, regime_width);
    point.poiseuille = regime_range(run.samples, Regime::poiseuille, 1.0, regime_width);
    point.hertz = regime_range(run.samples, Regime::hertz, 1.0, regime_width);
    point.h_crossover = analysis.h_crossover;
    point.kappa_crossover_exact =
        analysis.h_crossover ? crossover_kappa_paper(problem.material, *analysis.h_crossover) : NAN;
    return point;
}

} // namespace

PhaseDiagram phase_diagram(const PhaseDiagramSetup& setup, const std::function<void(double)>& progress)
{
    PhaseDiagram out;
    std::vector<double> log_h, log_kappa, decades;
    const int count = setup.kappa_count;
    for (long long i = 0; i < count; ++i) {
        const double kappa = setup.kappa_min * std::pow(setup.kappa_max / setup.kappa_min,
                                                        static_cast<double>(i) / (count - 1));
        ApproachProblem problem = setup.pair;
        problem.loading = constant_loading(kappa);
        const ApproachRun run = integrate_approach(problem, setup.settings);
        out.steps += run.steps;
        const PhaseDiagramPoint& point =
            out.points.emplace_back(phase_diagram_point(problem, run, kappa, setup.regime_width));
        const double window = point.poiseuille_decades();
        decades.push_back(window);
        if (window == 0.0 && !out.kappa_poiseuille_vanishes) out.kappa_poiseuille_vanishes = kappa;
        if (window > 0.0) out.kappa_poiseuille_last = kappa;
        if (point.h_crossover) {
            out.crossover_relative_error_max = std::max(out.crossover_relative_error_max,
                                                        std::abs(point.kappa_crossover_exact / kappa - 1.0));
            if (*point.h_crossover <= 1e-2) {
                log_h.push_back(std::log(*point.h_crossover));
                log_kappa.push_back(std::log(kappa));
            }
        }
        progress(static_cast<double>(i + 1) / static_cast<double>(count));
    }
    out.crossover_points = static_cast<int>(log_h.size());
    out.crossover_line = fit_line(log_h, log_kappa);
    out.poiseuille_window_nonincreasing = std::is_sorted(decades.rbegin(), decades.rend());
    return out;
}

} // namespace softgrain::sd
