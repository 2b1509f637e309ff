// Scenes of the shared core: `core.harmonic`.
#include "core/core_scenes.hpp"

#include "core/harmonic.hpp"
#include "core/output.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain {

namespace {

void run_harmonic(const Parameters& p, RunContext& context)
{
    const HarmonicOscillator oscillator{p.real("mass"), p.real("stiffness")};
    const double dt = p.real("dt");
    const double periods = p.real("periods");

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
    registry.add(Scene{
        "core.harmonic",
        "mass on a linear spring, velocity Verlet: period and energy error against theory",
        {
            ParameterSpec::real("mass", 1.0, "kg", "mass m").positive(),
            ParameterSpec::real("stiffness", 100.0, "N/m", "spring stiffness k").positive(),
            ParameterSpec::real("dt", 1e-3, "s", "time step; stable for dt < dt_c = 2 sqrt(m/k)").positive(),
            ParameterSpec::real("periods", 20.0, "1", "duration in periods T = 2 pi sqrt(m/k)").at_least(2.0),
        },
        run_harmonic,
    }
                     .without_vtk("a single mass on a spring, no particle to draw (its trajectory is in "
                                  "harmonic.dat)"));
}

} // namespace softgrain
