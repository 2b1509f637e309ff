// Scenes of the shared core: `core.harmonic`.
#include "core/core_scenes.hpp"

#include "core/harmonic.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain {

namespace {

// Units and meanings: harmonic_binding().
struct HarmonicOptions
{
    double mass = 1.0;
    double stiffness = 100.0;
    double dt = 1e-3;
    double periods = 20.0;
};

OptionBinding<HarmonicOptions> harmonic_binding()
{
    OptionBinding<HarmonicOptions> b;
    b.real(&HarmonicOptions::mass, "mass", "kg", "mass m").positive();
    b.real(&HarmonicOptions::stiffness, "stiffness", "N/m", "spring stiffness k").positive();
    b.real(&HarmonicOptions::dt, "dt", "s", "time step; stable for dt < dt_c = 2 sqrt(m/k)").positive();
    b.real(&HarmonicOptions::periods, "periods", "1", "duration in periods T = 2 pi sqrt(m/k)").at_least(2.0);
    return b;
}

void run_harmonic(const HarmonicOptions& options, RunContext& context)
{
    const HarmonicOscillator oscillator{options.mass, options.stiffness};
    const double dt = options.dt;
    const double periods = options.periods;

    auto& trajectory = context.table("trajectory.dat", {{"t", "s", "time"},
                                                        {"x", "m", "position"},
                                                        {"v", "m/s", "velocity"},
                                                        {"energy_error", "1", "E/E0 - 1"}});
    const long total_steps = harmonic_step_count(oscillator, dt, periods);
    const long stride = std::max(1L, total_steps / 2000); // at most ~2000 rows
    long step = 0;
    auto progress = context.progress("core.harmonic");
    const auto observe = [&](double t, double x, double v, double energy_error) {
        if (++step % stride == 0) trajectory.row({t, x, v, energy_error});
        if (step % 4096 == 0) progress.update(static_cast<double>(step) / static_cast<double>(total_steps));
    };
    const HarmonicRun run = simulate_harmonic(oscillator, dt, periods, observe);
    progress.finish();
    context.count_steps(run.steps);

    auto& s = context.summary();
    s["period"] = run.period;
    s["period_theory"] = oscillator.period();
    s["period_verlet_theory"] = verlet_period(oscillator, dt);
    s["energy_error_max"] = run.energy_error_max;
    s["energy_error_max_theory"] = verlet_energy_error_bound(oscillator, dt);
    s["dt_critical"] = oscillator.critical_time_step();
    s["dt_over_dt_critical"] = dt / oscillator.critical_time_step();
}

} // namespace

void register_core_scenes(SceneRegistry& registry)
{
    registry.add(
        bound_scene("core.harmonic",
                    "mass on a linear spring, velocity Verlet: period and energy error against theory",
                    harmonic_binding(), run_harmonic)
            .without_vtk("a single mass on a spring, no particle to draw (its trajectory is in "
                         "harmonic.dat)"));
}

} // namespace softgrain
