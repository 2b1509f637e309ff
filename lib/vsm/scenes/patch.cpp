// vsm.patch: patch tests A, B, C of VSM (Frenning 2022, Table 1): irregular particles in the unit cube under
// the linear field of eq. (52).
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "vsm/patch_test.hpp"
#include "vsm/scenes/parameters.hpp"
#include "vsm/scenes/scenes.hpp"
#include "vsm/vtk_frames.hpp"

namespace softgrain::vsm {

namespace {

// The setup of the library with `xi`, the one parameter that sets both contact factors of eq. (50).
struct PatchOptions
{
    PatchSetup setup;
    double xi = 1.0;
};

OptionBinding<PatchOptions> patch_binding()
{
    const auto setup = [](auto field) { return path(&PatchOptions::setup, field); };
    OptionBinding<PatchOptions> binding;
    binding.choice(setup(&PatchSetup::variant), "test",
                   {{"A", PatchVariant::A}, {"B", PatchVariant::B}, {"C", PatchVariant::C}},
                   "A: all particles prescribed, force error; B: displacement on all faces; C: "
                   "displacement on X3 = 0, tractions elsewhere");
    binding.integer(setup(&PatchSetup::per_side), "per_side", "1", "particles per side of the cube")
        .at_least(2);
    binding
        .real(setup(&PatchSetup::jitter), "jitter", "1",
              "uniform jitter of each coordinate, fraction of the spacing")
        .non_negative()
        .below(0.5);
    bind_jitter_seed(binding, setup(&PatchSetup::seed));
    binding.real(setup(&PatchSetup::alpha), "alpha", "1", "amplitude alpha of the linear field, eq. (52)")
        .positive();
    bind_material(binding, setup(&PatchSetup::material));
    bind_contact_factor(binding, &PatchOptions::xi);
    bind_internal_force(binding, path(&PatchOptions::setup, &PatchSetup::options, &ModelOptions::internal));
    binding
        .real(setup(&PatchSetup::ramp_time), "ramp_time", "s", "B, C: linear ramp of the loads (paper: 50 s)")
        .positive();
    binding
        .real(setup(&PatchSetup::hold_time), "hold_time", "s",
              "B, C: time at full load before the error is measured")
        .positive();
    binding.real(setup(&PatchSetup::cfl), "cfl", "1", "time step dt = cfl L_min / c_p")
        .positive()
        .at_most(1.0);
    bind_time_step_check(binding, setup(&PatchSetup::time_step_check));
    binding.real(setup(&PatchSetup::damping), "damping", "1/s", "B, C: mass-proportional damping coefficient")
        .non_negative();
    return binding;
}

// ParaView frames (time value t [s], field data load r(t) and test 1 A, 2 B, 3 C): test A has one state, the
// exact positions at which it measures the forces; B and C every 1000 time steps of the ramp and hold
// (--vtk-every N: every N steps) and always the final state, whose error the summary reports.
PatchObserver patch_frames(const PatchSetup& setup, RunContext& context)
{
    if (!context.vtk()) return {};
    return [&setup, &context](const PatchState& state) {
        if (!state.final && !context.vtk()->due(state.step, 1000)) return;
        context.vtk()->write(
            state.t, vsm_frame(state.model, state.x, state.v, state.t, state.step,
                               {{"load", state.load}, {"test", static_cast<double>(setup.variant) + 1}}));
    };
}

void report_patch(const PatchSetup& setup, const PatchResult& result, double relative_error,
                  RunContext& context)
{
    const bool static_test = setup.variant == PatchVariant::A;
    context.count_steps(result.steps);
    auto& particles =
        context.table("particles.dat", {{"X1", "m", "reference position"}, {"X2", "m", ""}, {"X3", "m", ""}});
    for (Eigen::Index a = 0; a < result.X.cols(); ++a)
        particles.row({result.X(0, a), result.X(1, a), result.X(2, a)});
    auto& summary = context.summary();
    summary["max_error"] = result.max_error;
    summary["test_id"] = static_cast<int>(setup.variant) + 1; // 1 = A, 2 = B, 3 = C (numeric, for tables)
    summary["max_error_unit"] = static_test ? "N" : "m";
    summary["relative_error"] = relative_error;
    summary["force_scale"] = result.force_scale;
    summary["final_residual_force"] = static_test ? nullptr : nlohmann::json(result.final_residual);
    summary["particles"] = result.particles;
    summary["dt"] = static_test ? nullptr : nlohmann::json(result.dt);
}

void run_patch(const PatchOptions& options, RunContext& context)
{
    PatchSetup setup = options.setup;
    setup.options = with_contact_factors(setup.options, options.xi);
    context.record_seed(setup.seed);
    const PatchResult result = run_patch_test(setup, patch_frames(setup, context));
    report_patch(setup, result, patch_relative_error(setup, result), context);
}

} // namespace

Scene patch_scene()
{
    return bound_scene("vsm.patch",
                       "VSM patch tests A, B, C (Frenning Table 1): irregular particles in the unit cube, "
                       "linear field eq. (52)",
                       patch_binding(), run_patch)
        .needing(patch_binding().estimate([](const PatchOptions& options) {
            return vsm_particle_memory(cube(double(options.setup.per_side)), "particles (per_side^3)");
        }))
        .with_vtk();
}

} // namespace softgrain::vsm
