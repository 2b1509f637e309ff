// Scenes of Soft Dynamics (Rognon & Gay): sd.approach, sd.phase_diagram, sd.many.
//
// Units of every scene: R = eta = E = 1 and F_ext = kappa, so that lengths are in R, forces in E R^2,
// velocities in V = F_ext/(eta R) (eq. 6) after division by kappa, and times in R/V.
#include "sd/sd_scenes.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "sd/approach.hpp"
#include "sd/approach_analysis.hpp"
#include "sd/many.hpp"
#include "sd/vtk_frames.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace softgrain {

namespace {

using namespace softgrain::sd;

std::vector<std::string> stepper_names()
{
    std::vector<std::string> names;
    for (const auto& s : gsl_steppers())
        names.push_back(s.name);
    return names;
}

// The default stepper: the cheapest that meets the accuracy on the Hertz regime (see reproductions/sd,
// sd-work-precision, and data/sd/decisions.toml, sd-default-stepper).
const char* const default_stepper = "rk8pd";

ApproachProblem pair_problem(double kappa, double h0, double h_min)
{
    const Material m; // R = E = eta = 1, alpha = 4/9
    if (!(h_min < h0))
        throw InputError("h_min = " + std::to_string(h_min) + " must be below h0 = " + std::to_string(h0));
    return {m, paper_contact_laws(m), constant_loading(kappa), h0, h_min};
}

// The integration parameters sd.approach and sd.phase_diagram share.
struct IntegratorChoice
{
    std::string stepper = default_stepper;
    double tolerance = 1e-10;
    int samples_per_decade = 20;
    double regime_width = 0.1;
};

template <class Options>
void bind_integrator(OptionBinding<Options>& b, IntegratorChoice Options::*integrator)
{
    b.word(path(integrator, &IntegratorChoice::stepper), "stepper", stepper_names(),
           "GSL ODE stepper for eqs. (7), (9)");
    b.real(path(integrator, &IntegratorChoice::tolerance), "tolerance", "1",
           "adaptive control: relative local error of h and delta per step")
        .positive()
        .below(1e-2);
    b.integer(path(integrator, &IntegratorChoice::samples_per_decade), "samples_per_decade", "1",
              "outputs per decade of h")
        .at_least(4);
    b.real(path(integrator, &IntegratorChoice::regime_width), "regime_width", "1",
           "a regime counts as reached where its first-order width w (Stokes (R/h)(3 - 2R/(R + delta)), "
           "Poiseuille h/R + 3 delta/h, Hertz 3h/R + 4h/(3 delta)) is at most this")
        .positive()
        .below(1.0);
}

IntegratorSettings adaptive_settings(const IntegratorChoice& integrator)
{
    IntegratorSettings settings;
    settings.stepper = integrator.stepper;
    settings.tolerance = integrator.tolerance;
    settings.samples_per_decade = static_cast<double>(integrator.samples_per_decade);
    return settings;
}

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
    OptionBinding<ApproachOptions> b;
    b.real(&ApproachOptions::kappa, "kappa", "1", "renormalised force F_ext/(E R^2), eq. (6)")
        .positive()
        .at_most(1.0);
    b.real(&ApproachOptions::h0, "h0", "R", "initial gap (the paper: 100 R)").positive();
    b.real(&ApproachOptions::h_min, "h_min", "R", "the run stops when h reaches h_min").positive();
    b.choice(&ApproachOptions::fixed_step, "step_control", {{"adaptive", false}, {"fixed", true}},
             "adaptive error control, or a fixed step dt (stability study)");
    b.real(&ApproachOptions::dt, "dt", "R/V", "fixed step (step_control = fixed)").positive();
    b.integer(&ApproachOptions::max_steps, "max_steps", "1", "guard against a stalled run").at_least(1);
    b.integer(&ApproachOptions::timing_repeats, "timing_repeats", "1",
              "integrations timed (best of); results are identical")
        .at_least(1);
    bind_integrator(b, &ApproachOptions::integrator);
    return b;
}

void run_approach(const ApproachOptions& options, RunContext& context)
{
    const double kappa = options.kappa;
    const ApproachProblem problem = pair_problem(kappa, options.h0, options.h_min);
    IntegratorSettings settings = adaptive_settings(options.integrator);
    settings.fixed_step = options.fixed_step;
    settings.dt = options.dt / kappa; // R/V = eta R^2 / F = 1/kappa in scene units
    settings.max_steps = options.max_steps;

    // Wall time of the integration alone (best of `timing_repeats`, the runs being identical).
    ApproachRun run;
    double seconds = INFINITY;
    for (int r = 0; r < options.timing_repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        run = integrate_approach(problem, settings);
        seconds = std::min(seconds, seconds_since(start));
    }
    context.count_steps(run.steps);
    const ApproachAnalysis an = analyse_approach(problem, run.samples, options.integrator.regime_width);
    // ParaView frames, one per row of approach.dat (--vtk-every N: every N-th), time value t in R/V as there:
    // the two spheres and their pair, field data time t [s] and gap_min h [m].
    if (auto* series = context.vtk())
        for (const ApproachSample& s : run.samples) {
            if (!series->next()) continue;
            std::vector<vtk::Part> parts = approach_frame(problem, s);
            for (auto& part : parts) {
                part.data.field("time", s.t);
                part.data.field("gap_min", s.h);
            }
            series->write(s.t * kappa, parts);
        }

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
    const double R = problem.material.radius;
    double stiffness_max = 0; // max over the samples of -Re(eigenvalue) h/|h-dot|
    for (std::size_t k = 0; k < run.samples.size(); ++k) {
        const ApproachSample& s = run.samples[k];
        const ModeRates modes = jacobian_modes(problem, s.t, s.X, s.h);
        stiffness_max = std::max(stiffness_max, -modes.fast);
        table.row({s.t * kappa, s.X, s.h, s.rates.delta, s.rates.a, s.rates.h_dot / kappa,
                   s.rates.X_dot / kappa, an.exponents.lambda1[k], an.exponents.lambda2[k],
                   an.lambda1_exact[k], an.lambda2_exact[k], an.force_balance_residual[k],
                   an.deflection_residual[k], an.h_error[k],
                   regime_width(Regime::stokes, R, s.h, s.rates.delta),
                   regime_width(Regime::poiseuille, R, s.h, s.rates.delta),
                   regime_width(Regime::hertz, R, s.h, s.rates.delta), modes.fast, modes.slow});
    }

    auto& sum = context.summary();
    const auto regime = [&](const char* name, const std::optional<RegimePoint>& point) {
        const std::string key(name);
        sum["lambda1_" + key] = point ? nlohmann::json(point->lambda1) : nlohmann::json(nullptr);
        sum["lambda2_" + key] = point ? nlohmann::json(point->lambda2) : nlohmann::json(nullptr);
        sum["h_" + key] = point ? nlohmann::json(point->h) : nlohmann::json(nullptr);
        sum["width_" + key] = point ? nlohmann::json(point->width) : nlohmann::json(nullptr);
    };
    regime("stokes", an.stokes);
    regime("poiseuille", an.poiseuille);
    regime("hertz", an.hertz);
    const ApproachSample& first = run.samples.front();
    const ApproachSample& last = run.samples.back();
    sum["h_crossover"] = value_or_null(an.h_crossover);
    sum["kappa_crossover_exact"] =
        an.h_crossover ? nlohmann::json(crossover_kappa_paper(problem.material, *an.h_crossover))
                       : nlohmann::json(nullptr);
    sum["kappa_crossover_asymptotic"] =
        an.h_crossover ? nlohmann::json(crossover_kappa_asymptotic(problem.material, *an.h_crossover))
                       : nlohmann::json(nullptr);
    sum["lambda_error_max"] = an.lambda_error_max;
    sum["force_balance_residual_max"] =
        *std::max_element(an.force_balance_residual.begin(), an.force_balance_residual.end());
    sum["deflection_residual_max"] =
        *std::max_element(an.deflection_residual.begin(), an.deflection_residual.end());
    sum["h_error_max"] = *std::max_element(an.h_error.begin(), an.h_error.end());
    double hertz_error = -1;
    for (std::size_t k = 0; k < run.samples.size(); ++k)
        if (regime_width(Regime::hertz, R, run.samples[k].h, run.samples[k].rates.delta) <=
            options.integrator.regime_width)
            hertz_error = std::max(hertz_error, an.h_error[k]);
    sum["h_error_hertz"] = hertz_error >= 0 ? nlohmann::json(hertz_error) : nlohmann::json(nullptr);
    sum["stiffness_max"] = stiffness_max;
    sum["h_final"] = last.h;
    sum["t_final"] = last.t * kappa;
    sum["delta_start"] = first.rates.delta;
    sum["delta_end"] = last.rates.delta;
    sum["a_end"] = last.rates.a;
    sum["h_dot_start"] = first.rates.h_dot / kappa;
    sum["samples"] = run.samples.size();
    sum["steps"] = run.steps;
    sum["rhs_evaluations"] = run.rhs_evaluations;
    sum["integration_wall_time_s"] = seconds;
    sum["stepper_index"] = find_stepper(settings.stepper).index;
    sum["stepper_implicit"] = find_stepper(settings.stepper).implicit;
    sum["dt_lambda_max"] = settings.fixed_step ? nlohmann::json(run.dt_lambda_max) : nlohmann::json(nullptr);
    // The fastest rate of the balanced dynamics along the path, max |d h-dot/dh| (from a log scan of h), in
    // V/R.
    double rate_max = 0;
    for (double h = problem.h0; h >= problem.h_min; h /= std::pow(10.0, 0.05))
        rate_max = std::max(rate_max, std::abs(gap_rate_derivative(problem, h, 0.0)));
    sum["gap_rate_derivative_max"] = rate_max / kappa;
}

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
    OptionBinding<PhaseDiagramOptions> b;
    b.real(&PhaseDiagramOptions::kappa_min, "kappa_min", "1", "smallest kappa (the paper: 1e-6)").positive();
    b.real(&PhaseDiagramOptions::kappa_max, "kappa_max", "1", "largest kappa (the paper: 0.3)")
        .positive()
        .at_most(1.0);
    b.integer(&PhaseDiagramOptions::kappa_count, "kappa_count", "1", "log-spaced kappa values").at_least(2);
    b.real(&PhaseDiagramOptions::h0, "h0", "R", "initial gap (the paper: 100 R)").positive();
    b.real(&PhaseDiagramOptions::h_min, "h_min", "R", "final gap").positive();
    bind_integrator(b, &PhaseDiagramOptions::integrator);
    b.check([](const PhaseDiagramOptions& o) {
        if (!(o.kappa_min < o.kappa_max))
            throw InputError("kappa_min = " + std::to_string(o.kappa_min) +
                             " must be below kappa_max = " + std::to_string(o.kappa_max));
    });
    return b;
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
        const ApproachAnalysis an = analyse_approach(problem, run.samples, threshold);
        const std::optional<GapRange> ranges[3] = {
            regime_range(run.samples, Regime::stokes, 1.0, threshold),
            regime_range(run.samples, Regime::poiseuille, 1.0, threshold),
            regime_range(run.samples, Regime::hertz, 1.0, threshold)};
        const auto low = [&](int r) { return ranges[r] ? ranges[r]->low : NAN; };
        const auto high = [&](int r) { return ranges[r] ? ranges[r]->high : NAN; };
        const double window = ranges[1] ? ranges[1]->decades() : 0.0;
        decades.push_back(window);
        if (window == 0.0 && std::isnan(kappa_vanishes)) kappa_vanishes = kappa;
        if (window > 0.0) kappa_last_window = kappa;
        const double hc = an.h_crossover.value_or(NAN);
        const double kc = an.h_crossover ? crossover_kappa_paper(problem.material, hc) : NAN;
        if (an.h_crossover) {
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
    const Material m;
    for (double h = 1e-7; h <= 1.0 + 1e-12; h *= std::pow(10.0, 0.1))
        lines.row({h, crossover_kappa_paper(m, h), crossover_kappa_asymptotic(m, h)});

    auto& sum = context.summary();
    sum["kappa_runs"] = count;
    sum["crossover_rel_error_max"] = relative_error_max;
    sum["crossover_points"] = log_h.size();
    if (const auto line = fit_line(log_h, log_kappa)) {
        sum["crossover_slope"] = line->slope;
        sum["crossover_prefactor"] = std::exp(line->intercept);
    } else {
        sum["crossover_slope"] = nullptr;
        sum["crossover_prefactor"] = nullptr;
    }
    sum["poiseuille_decades_at_kappa_min"] = decades.front();
    sum["kappa_poiseuille_vanishes"] = finite_or_null(kappa_vanishes);
    sum["kappa_poiseuille_last"] = finite_or_null(kappa_last_window);
    sum["poiseuille_window_nonincreasing"] = std::is_sorted(decades.rbegin(), decades.rend());
}

// The centres carry the deflection through eq. (2), |X_ij| = 2R + h - 2 delta: a deflection below what the
// centre distance resolves to the integration tolerance (|X| ulp / tolerance) would give F_ela = 0 and a
// system that never moves (force = 1e-30 once ran to exit 0 with the gaps unchanged).
void refuse_unresolved_deflection(double delta0, double distance0, double tolerance, double force)
{
    const double resolved = (std::nextafter(distance0, 2 * distance0) - distance0) / tolerance;
    if (!(delta0 >= resolved))
        throw InputError("'force' = " + number_text(force) +
                         " gives the elastic deflection delta0 = " + number_text(delta0) +
                         " R, which the centre distance |X| = " + number_text(distance0) +
                         " R resolves only to " + number_text(resolved) +
                         " R at tolerance = " + number_text(tolerance) +
                         "; allowed: a force whose deflection is resolved (a larger force or tolerance)");
}

// The run is asked to bring the smallest gap to h_min (the integration stops there, or at the pair
// reference's approach time, which the integration tolerance lets it miss by far less than 1e-6 h_min);
// a run that stops short ends as a diagnosed failure, never as a summary.
void require_approach_completed(double gap_final, double h_min, long steps)
{
    if (!(gap_final <= h_min * (1 + 1e-6)))
        throw NumericalError("the smallest gap, h = " + number_text(gap_final) + " R", steps,
                             "it did not reach h_min = " + number_text(h_min) +
                                 " R by the pair reference's approach time");
}

struct ManyOptions
{
    int particles = 2;
    bool line = true;              // a line compressed at its ends, else a triangle pushed to its centre
    double force = 1e-3;           // [E R^2]
    double h0 = 1.0, h_min = 1e-4; // [R]
    double tolerance = 1e-10;
    int outputs = 120;
};

OptionBinding<ManyOptions> many_binding()
{
    OptionBinding<ManyOptions> b;
    b.integer(&ManyOptions::particles, "particles", "1", "number of particles").at_least(2).at_most(64);
    b.choice(&ManyOptions::line, "geometry", {{"line", true}, {"cluster", false}},
             "a line compressed at its ends, or a triangle (particles = 3) pushed to its centre");
    b.real(&ManyOptions::force, "force", "E R^2", "external force on each loaded particle (kappa)")
        .positive()
        .at_most(1.0);
    b.real(&ManyOptions::h0, "h0", "R", "initial gap of every bond").positive();
    b.real(&ManyOptions::h_min, "h_min", "R", "stop when the smallest gap reaches h_min").positive();
    b.real(&ManyOptions::tolerance, "tolerance", "1", "rk8pd relative (and delta-scaled absolute) tolerance")
        .positive()
        .below(1e-2);
    b.integer(&ManyOptions::outputs, "outputs", "1",
              "output times, log-spaced over the 7 decades before the pair reaches h_min")
        .at_least(4);
    b.check([](const ManyOptions& o) {
        if (!o.line && o.particles != 3)
            throw InputError(
                "geometry = cluster needs particles = 3 (an equilateral triangle); got particles = " +
                std::to_string(o.particles));
        if (!(o.h_min < o.h0)) throw InputError("h_min must be below h0");
    });
    return b;
}

void run_many(const ManyOptions& options, RunContext& context)
{
    const long long n = options.particles;
    const bool line = options.line;
    const double F = options.force, h0 = options.h0, h_min = options.h_min;
    const Material m;
    ManyParticleSystem system{m, paper_contact_laws(m), line ? 1 : 2, {}, {}};
    // Pair force of every bond in the balanced configuration: F on a line, F/(2 sin(pi/3)) = F/sqrt3 in the
    // triangle (two bonds at 30 degrees from the inward radius of each particle).
    const double pair_force = line ? F : F / std::sqrt(3.0);
    const double delta0 = balanced_deflection(system.laws, h0, pair_force);
    const double distance0 = 2.0 * m.radius + h0 - 2.0 * delta0; // eq. (2)
    refuse_unresolved_deflection(delta0, distance0, options.tolerance, F);
    std::vector<double> positions;
    if (line) {
        for (long long i = 0; i < n; ++i)
            positions.push_back(static_cast<double>(i) * distance0);
        for (long long i = 0; i + 1 < n; ++i)
            system.bonds.push_back({static_cast<int>(i), static_cast<int>(i + 1)});
        system.external = [n, F](double, std::vector<double>& force, std::vector<double>& rate) {
            std::fill(force.begin(), force.end(), 0.0);
            std::fill(rate.begin(), rate.end(), 0.0);
            force.front() = F;
            force[n - 1] = -F;
        };
    } else {
        const double radius = distance0 / std::sqrt(3.0);
        for (int i = 0; i < 3; ++i) {
            const double angle = std::numbers::pi / 2 + 2.0 * std::numbers::pi * i / 3.0;
            positions.push_back(radius * std::cos(angle));
            positions.push_back(radius * std::sin(angle));
        }
        system.bonds = {{0, 1}, {1, 2}, {2, 0}};
        const std::vector<double> initial = positions;
        system.external = [F, initial](double, std::vector<double>& force, std::vector<double>& rate) {
            for (int i = 0; i < 3; ++i) { // toward the centre of the triangle (fixed direction)
                const double norm = std::hypot(initial[2 * i], initial[2 * i + 1]);
                force[2 * i] = -F * initial[2 * i] / norm;
                force[2 * i + 1] = -F * initial[2 * i + 1] / norm;
            }
            std::fill(rate.begin(), rate.end(), 0.0);
        };
    }
    const std::vector<double> gaps(system.bonds.size(), h0);
    // The pair reference: the same bond alone under pair_force (eq. 7 with eq. 1), by quadrature.
    const ApproachProblem pair{m, system.laws, constant_loading(pair_force), h0, h_min};
    const double t_end = approach_time_reference(pair, h0, h_min);
    std::vector<double> times;
    const long long outputs = options.outputs;
    for (long long k = 1; k <= outputs; ++k)
        times.push_back(t_end * std::pow(1e-7, 1.0 - static_cast<double>(k) / outputs) *
                        (k == outputs ? 1.0 + 1e-9 : 1.0));
    long steps = 0;
    const std::vector<ManySample> samples =
        integrate_many(system, positions, gaps, times, h_min, options.tolerance, delta0, steps);
    context.count_steps(steps);
    // ParaView frames, one per output sample (--vtk-every N: every N-th) as in many.dat, time value t in
    // R/V: the particles and the pairs, field data time t [s] and gap_min h [m].
    if (auto* series = context.vtk())
        for (const ManySample& s : samples) {
            if (!series->next()) continue;
            std::vector<vtk::Part> parts = many_particle_frame(system, s);
            for (auto& part : parts) {
                part.data.field("time", s.t);
                part.data.field("gap_min", *std::min_element(s.gaps.begin(), s.gaps.end()));
            }
            series->write(s.t * F, parts);
        }

    std::vector<Column> columns{{"t", "R/V", "time, V = force/(eta R)"}};
    for (std::size_t b = 0; b < system.bonds.size(); ++b)
        columns.push_back({"h_" + std::to_string(b), "R", "gap of bond " + std::to_string(b)});
    for (long long i = 0; i < n; ++i)
        for (int c = 0; c < system.dimension; ++c)
            columns.push_back({"v_" + std::to_string(i) + (c == 0 ? "x" : "y"), "V", "centre velocity"});
    auto& table = context.table("many.dat", columns);

    double mean_velocity_max = 0, symmetry_max = 0, pair_error_max = 0, balance_max = 0, residual_max = 0;
    std::vector<double> t_ref(system.bonds.size(), 0.0), previous_h(system.bonds.size(), h0);
    for (const ManySample& s : samples) {
        std::vector<double> row{s.t * F};
        row.insert(row.end(), s.gaps.begin(), s.gaps.end());
        for (double v : s.rates.velocity)
            row.push_back(v / F);
        table.row(row);
        const double v_scale =
            *std::max_element(s.rates.velocity.begin(), s.rates.velocity.end(),
                              [](double a, double b) { return std::abs(a) < std::abs(b); });
        for (int c = 0; c < system.dimension; ++c) {
            double mean = 0;
            for (long long i = 0; i < n; ++i)
                mean += s.rates.velocity[i * system.dimension + c] / n;
            if (v_scale != 0) mean_velocity_max = std::max(mean_velocity_max, std::abs(mean / v_scale));
        }
        const auto [lo, hi] = std::minmax_element(s.gaps.begin(), s.gaps.end());
        symmetry_max = std::max(symmetry_max, (*hi - *lo) / *lo);
        // Every bond against the pair reference (the same for all bonds by symmetry or statics).
        for (std::size_t b = 0; b < s.gaps.size(); ++b) {
            if (s.gaps[b] < previous_h[b])
                t_ref[b] += approach_time_reference(pair, previous_h[b], s.gaps[b]);
            previous_h[b] = s.gaps[b];
            pair_error_max = std::max(pair_error_max,
                                      std::abs(s.rates.gap_rate[b]) * std::abs(s.t - t_ref[b]) / s.gaps[b]);
            balance_max = std::max(balance_max, std::abs(s.rates.pair_force[b] / pair_force - 1.0));
        }
        residual_max = std::max(residual_max, s.rates.residual);
    }
    const double gap_final = *std::min_element(samples.back().gaps.begin(), samples.back().gaps.end());
    require_approach_completed(gap_final, h_min, steps);
    auto& sum = context.summary();
    sum["particles"] = n;
    sum["bonds"] = system.bonds.size();
    sum["pair_force"] = pair_force;
    sum["mean_velocity_max"] = mean_velocity_max;
    sum["symmetry_deviation_max"] = symmetry_max;
    sum["pair_reference_error_max"] = pair_error_max;
    sum["pair_force_residual_max"] = balance_max;
    sum["linear_system_residual_max"] = residual_max;
    sum["gap_final_min"] = gap_final;
    sum["t_final"] = samples.back().t * F;
}

} // namespace

void register_sd_scenes(SceneRegistry& registry)
{
    registry.add(bound_scene("sd.approach",
                             "two lubricated elastic spheres under constant force: delta(h), h-dot(h), local "
                             "exponents (SD Fig. 3)",
                             approach_binding(), run_approach)
                     .with_vtk());
    registry.add(
        bound_scene(
            "sd.phase_diagram",
            "regimes crossed by constant-kappa approaches and the Poiseuille-Hertz crossover (SD Fig. 3b)",
            phase_diagram_binding(), run_phase_diagram)
            .without_vtk("a sweep of independent approaches over kappa, each ending at h = h_min: not a "
                         "time series; draw one approach with sd.approach --set kappa=K --vtk"));
    registry.add(bound_scene("sd.many",
                             "several particles, note [20]: centre velocities from the linear system, gaps "
                             "from eq. (7)",
                             many_binding(), run_many)
                     .with_vtk());
}

} // namespace softgrain
