// spd.ring_pressure (Trivino et al., eqs. (19)-(25)): a ring under a small internal pressure, relaxed
// without and with its core; the apparent moduli K_shell and K_e against theory.
#include "core/errors.hpp"
#include "core/output.hpp"
#include "spd/calibration.hpp"
#include "spd/ring.hpp"
#include "spd/scenes/parameters.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/vtk_frames.hpp"

#include <cmath>
#include <functional>

namespace softgrain::spd {

namespace {

// spd.ring_pressure's options: the ring and the pressure applied inside it.
struct RingPressureOptions
{
    RingSetup ring;
    double pressure = 0.05; // [Pa]
};

OptionBinding<RingPressureOptions> ring_pressure_binding()
{
    OptionBinding<RingPressureOptions> binding;
    bind_ring(binding, &RingPressureOptions::ring);
    binding.real(&RingPressureOptions::pressure, "pressure", "Pa", "applied internal pressure (small)")
        .positive();
    binding.check([](const RingPressureOptions& options) {
        if (std::isinf(options.ring.eta))
            throw InputError(
                "eta = inf: an incompressible core has no volume change under pressure, so K_e is "
                "infinite; allowed: a finite eta >= 0");
    });
    return binding;
}

// The ring relaxed under the pressure without its core (eta = 0: K_shell) and with it (K_e).
struct RingPressureRun
{
    RingPressureResult shell, total;
};

void report_ring_pressure(const RingSetup& setup, const RingPressureRun& run, RunContext& context)
{
    const RingScales scales = ring_scales(setup);
    auto& summary = context.summary();
    summary["K_shell"] = run.shell.K_measured;
    summary["K_shell_theory"] = scales.K_shell;
    summary["K_shell_printed_approximation"] = 2 * M_PI / (setup.nodes * setup.material.s) * scales.laws.k_s;
    summary["K_effective"] = run.total.K_measured;
    summary["K_effective_theory"] = effective_bulk_modulus(setup.eta, scales.K_shell);
    summary["volume_strain"] = run.total.volume_strain;
}

void run_ring_pressure(const RingPressureOptions& options, RunContext& context)
{
    const RingSetup& setup = options.ring;
    const double pressure = options.pressure;
    RingSetup shell_only = setup;
    shell_only.eta = 0;
    // ParaView frames, one per pressure state: the relaxed ring without its core (eta = 0, state 0; K_shell)
    // and with it (state 1; K_e). Time value: the state index; field data pressure [Pa] and eta.
    const auto frame = [&](double eta, double state) {
        return [&context, eta, state, pressure](const ShellModel& model, int ring) {
            if (!context.vtk()->next()) return;
            vtk::PolyData particles = shell_particles(model, {ring});
            particles.field("state", state);
            particles.field("pressure", pressure);
            particles.field("eta", eta);
            context.vtk()->write(state, {{"particles", std::move(particles)}});
        };
    };
    using Relaxed = std::function<void(const ShellModel&, int)>;
    const RingPressureRun run{
        ring_under_pressure(shell_only, pressure, context.vtk() ? frame(0.0, 0) : Relaxed{}),
        ring_under_pressure(setup, pressure, context.vtk() ? frame(setup.eta, 1) : Relaxed{})};
    context.count_steps(run.shell.steps + run.total.steps);
    report_ring_pressure(setup, run, context);
}

} // namespace

Scene ring_pressure_scene()
{
    return bound_scene(
               "spd.ring_pressure",
               "SPD eqs. (19)-(25): ring under small internal pressure; K_shell and K_e against theory",
               ring_pressure_binding(), run_ring_pressure)
        .needing(ring_pressure_binding().estimate([](const RingPressureOptions& options) {
            return shell_model_memory(options.ring.nodes, "vertices (nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::spd
