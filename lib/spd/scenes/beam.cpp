// spd.beam (Trivino et al., section 3, Figs. 7-8): a cantilever or simply supported beam under a point
// force, relaxed to equilibrium, against beam theory.
#include "spd/beam.hpp"
#include "core/errors.hpp"
#include "core/output.hpp"
#include "spd/scenes/parameters.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/vtk_frames.hpp"

#include <string>

namespace softgrain::spd {

namespace {

// spd.beam's options: the beam and the time step of its relaxation.
struct BeamOptions
{
    BeamSetup beam;
    double dt_factor = 0.5;
};

// The scene's defaults where they differ from the library's.
BeamOptions beam_defaults()
{
    BeamOptions options;
    options.beam.nodes = 153;
    options.beam.material = {1e6, 0.3, 0.05, 0.1};
    options.beam.force = 1e-3;
    return options;
}

OptionBinding<BeamOptions> beam_binding()
{
    const auto beam = [](auto field) { return path(&BeamOptions::beam, field); };
    OptionBinding<BeamOptions> binding(beam_defaults());
    binding.choice(
        beam(&BeamSetup::support), "support",
        {{"cantilever", BeamSupport::cantilever}, {"simple", BeamSupport::simple}},
        "cantilever (clamped at x = 0, force at the tip) or simply supported (force at the centre)");
    binding
        .integer(beam(&BeamSetup::nodes), "nodes", "1",
                 "nodes N along the beam (odd for simple support); 153 is the smallest giving both "
                 "supports 1% accuracy against beam theory (spd-beam-work-precision)")
        .at_least(3);
    binding.real(beam(&BeamSetup::length), "length", "m", "beam length L").positive();
    binding
        .real(beam(&BeamSetup::force), "force", "N",
              "point force F (small: linear theory, delta_max < 0.01 L)")
        .positive();
    binding
        .real(&BeamOptions::dt_factor, "dt_factor", "1", "time step over dt_c = sqrt(m/k_max) (section 2.4)")
        .positive();
    bind_shell_material(binding, beam(&BeamSetup::material));
    binding.check([](const BeamOptions& options) {
        const BeamSetup& setup = options.beam;
        const double theory = beam_deflection_max_theory(setup);
        if (theory > 0.01 * setup.length)
            throw InputError("force = " + std::to_string(setup.force) +
                             ": the point-load theory is linear; allowed: a force "
                             "giving delta_max < 0.01 length (here " +
                             std::to_string(theory / setup.length) + " length)");
    });
    return binding;
}

// The deflection profile against the point-load shapes, and the deflection against theory.
void report_beam(const BeamSetup& setup, const BeamResult& result, RunContext& context)
{
    const bool cantilever = setup.support == BeamSupport::cantilever;
    auto& profile =
        context.table("profile.dat", {{"x_over_L", "1", "node position x/L"},
                                      {"delta", "m", "downward deflection"},
                                      {"delta_over_max", "1", "delta/delta_max"},
                                      {"theory", "1", "point-load shape: eq. (14) or 3 xi - 4 xi^3"},
                                      {"eq16_printed", "1", "eq. (16) as printed (uniform-load shape)"}});
    for (std::size_t k = 0; k < result.x.size(); ++k) {
        const double xi = result.x[k] / setup.length;
        profile.row({xi, result.deflection[k], result.deflection[k] / result.deflection_max,
                     cantilever ? cantilever_shape(xi) : simple_point_load_shape(xi),
                     simple_uniform_load_shape_eq16(xi)});
    }
    const double theory = beam_deflection_max_theory(setup);
    auto& summary = context.summary();
    summary["deflection_max"] = result.deflection_max;
    summary["deflection_max_theory"] = theory;
    summary["ratio"] = result.deflection_max / theory;
    summary["ratio_discrete_theory"] = beam_discrete_ratio(setup.support, setup.nodes);
    summary["inverse_nodes"] = 1.0 / setup.nodes;
    summary["support_index"] = cantilever ? 0 : 1;
    summary["dt"] = result.dt;
    summary["dt_critical"] = result.critical_time_step;
}

void run_beam(const BeamOptions& options, RunContext& context)
{
    const BeamSetup& setup = options.beam;
    // ParaView frames of the damped relaxation, in which the beam settles from straight into its deflected
    // shape: the load applied (step 0), every 1000th force check (16 000 steps; --vtk-every N: every N-th
    // check, 16 N steps) and always the relaxed state, the one profile.dat lists. Time value: the step.
    const BeamObserver frame = [&](const ShellModel& model, long step, bool relaxed) {
        vtk::Series& series = *context.vtk();
        if (!relaxed && !series.next(1000)) return;
        vtk::PolyData beam = shell_walls(model, {0});
        beam.field("force", setup.force);
        beam.field("step", static_cast<double>(step));
        beam.field("relaxed", relaxed ? 1.0 : 0.0);
        series.write(static_cast<double>(step), {{"beam", std::move(beam)}});
    };
    const BeamResult result = simulate_beam(setup, options.dt_factor, beam_force_tolerance_relative,
                                            context.vtk() ? frame : BeamObserver{});
    context.count_steps(result.steps);
    report_beam(setup, result, context);
}

} // namespace

Scene beam_scene()
{
    return bound_scene("spd.beam",
                       "SPD section 3: cantilever or simply supported beam under a point force, against beam "
                       "theory",
                       beam_binding(), run_beam)
        .needing(beam_binding().estimate([](const BeamOptions& options) {
            return shell_model_memory(options.beam.nodes, "vertices (nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::spd
