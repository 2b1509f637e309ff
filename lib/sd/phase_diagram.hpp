// Rognon & Gay, Fig. 3(b): the regimes that constant-kappa approaches cross and their Poiseuille-Hertz
// crossover, over log-spaced kappa. Each kappa is one approach of the pair (approach.hpp) from h0 to h_min
// under constant loading, analysed by approach_analysis.hpp: the gap range where each regime's width is at
// most regime_width, and the gap h where delta = h, against the paper's delta = h line
// kappa = alpha sqrt 2 (h/R) sqrt(h-bar/R + h/R) (crossover_kappa_paper, scaling.hpp).
#pragma once

#include "core/fits.hpp"
#include "sd/approach.hpp"
#include "sd/approach_analysis.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace softgrain::sd {

struct PhaseDiagramSetup
{
    ApproachProblem pair; // material, the paper's laws, h0 and h_min; the loading is each kappa's, constant
    double kappa_min = 1e-6, kappa_max = 0.3;
    int kappa_count = 12; // kappa_min ... kappa_max log-spaced, both ends included
    IntegratorSettings settings;
    double regime_width = 0.1;
};

// One approach: its gaps, the ranges of h in each regime (empty: never reached), and its crossover.
struct PhaseDiagramPoint
{
    double kappa = 0;
    double h_start = 0, h_end = 0; // its first and last sample
    std::optional<GapRange> stokes, poiseuille, hertz;
    std::optional<double> h_crossover; // simulated h where delta = h
    double kappa_crossover_exact = 0;  // crossover_kappa_paper at h_crossover (NaN without one)
    double poiseuille_decades() const; // log10 of the Poiseuille range, 0 if none
};

struct PhaseDiagram
{
    std::vector<PhaseDiagramPoint> points; // ascending kappa
    long steps = 0;                        // of every integration
    // The crossovers against the paper's line: the largest |kappa_exact / kappa - 1|, and the fit of
    // ln kappa = ln prefactor + slope ln h_crossover over those on its asymptotic branch kappa ~ (h/R)^(3/2)
    // (h_crossover <= 1e-2 R, where h-bar = h within 1 %).
    double crossover_relative_error_max = 0;
    int crossover_points = 0;
    std::optional<Line> crossover_line;
    // The Poiseuille window: the smallest kappa without one, the largest with one, and whether its width in
    // decades never grows with kappa.
    std::optional<double> kappa_poiseuille_vanishes, kappa_poiseuille_last;
    bool poiseuille_window_nonincreasing = true;
};

// progress(fraction) after each approach. Throws NumericalError as integrate_approach does.
PhaseDiagram phase_diagram(const PhaseDiagramSetup& setup, const std::function<void(double)>& progress);

} // namespace softgrain::sd
