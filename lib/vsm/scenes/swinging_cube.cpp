// vsm.swinging_cube: the swinging cube of VSM (Frenning 2022, Fig. 5): the displacement error against the
// linear solution eq. (53) at t = 5 ms.
#include "vsm/swinging_cube.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "vsm/scenes/parameters.hpp"
#include "vsm/scenes/scenes.hpp"
#include "vsm/vtk_frames.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

namespace softgrain::vsm {

namespace {

// The setup of the library with the scene's scale of the mode amplitudes, the one `xi` of both contact
// factors of eq. (50), and the samples of the error history.
struct SwingingCubeOptions
{
    SwingingCubeSetup setup;
    double amplitude_scale = 1.0;
    double xi = 1.0;
    int history_samples = 20;
};

// The library's setup at these options: amplitudes scaled, xi_n = xi_t = xi.
SwingingCubeSetup swinging_cube_setup(const SwingingCubeOptions& options)
{
    SwingingCubeSetup setup = options.setup;
    setup.cube.amplitude *= options.amplitude_scale;
    setup.options = with_contact_factors(setup.options, options.xi);
    return setup;
}

// The displacement must be resolved in positions of order 1 m: below 1e-10 m its rounding (2e-6 relative)
// approaches the discretisation error the scene measures, and at 1e-300 the relative errors were 0/0.
void refuse_unresolved_amplitude(const SwingingCubeOptions& options)
{
    const double amplitude = swinging_cube_setup(options).cube.amplitude.cwiseAbs().maxCoeff();
    if (!(amplitude >= 1e-10))
        throw InputError("'amplitude_scale' = " + number_text(options.amplitude_scale) +
                         " makes the largest displacement amplitude " + number_text(amplitude) +
                         " m; allowed: amplitudes of at least 1e-10 m (resolved in positions of order 1 m)");
}

OptionBinding<SwingingCubeOptions> swinging_cube_binding()
{
    const auto setup = [](auto field) { return path(&SwingingCubeOptions::setup, field); };
    OptionBinding<SwingingCubeOptions> binding;
    binding
        .integer(setup(&SwingingCubeSetup::per_side), "per_side", "1", "particles per side of the unit cube")
        .at_least(3);
    binding
        .real(setup(&SwingingCubeSetup::jitter), "jitter", "1",
              "uniform jitter of each coordinate, fraction of the spacing")
        .non_negative()
        .below(0.5);
    bind_jitter_seed(binding, setup(&SwingingCubeSetup::seed));
    bind_material(binding,
                  path(&SwingingCubeOptions::setup, &SwingingCubeSetup::cube, &SwingingCube::material));
    binding
        .real(&SwingingCubeOptions::amplitude_scale, "amplitude_scale", "1",
              "factor on (U1, U2, U3) = (5e-4, 5e-4, -1e-3) m (linear-regime check)")
        .positive();
    bind_contact_factor(binding, &SwingingCubeOptions::xi);
    bind_internal_force(
        binding, path(&SwingingCubeOptions::setup, &SwingingCubeSetup::options, &ModelOptions::internal));
    binding.real(setup(&SwingingCubeSetup::end_time), "end_time", "s", "time at which the error is measured")
        .positive();
    binding
        .integer(&SwingingCubeOptions::history_samples, "history_samples", "1",
                 "samples of the error history (error_history.dat), besides t = 0")
        .non_negative();
    binding
        .real(setup(&SwingingCubeSetup::cfl), "cfl", "1",
              "time step dt = cfl L_min / c_p (rounded down to hit end_time)")
        .positive()
        .at_most(2.0);
    bind_time_step_check(binding, setup(&SwingingCubeSetup::time_step_check));
    binding.check(refuse_unresolved_amplitude);
    return binding;
}

// ParaView frames at every time step (--vtk-every N: every N-th), time value t [s]; field data cos_omega_t,
// the exact mode amplitude of eq. (53).
StepObserver swinging_cube_frames(const SwingingCube& cube, RunContext& context)
{
    if (!context.vtk()) return {};
    return [omega = cube.angular_frequency(), &context](const Model& model, const Leapfrog& integrator) {
        if (context.vtk()->due(integrator.state().step))
            context.vtk()->write(
                integrator.state().t,
                vsm_frame(model, integrator, {{"cos_omega_t", std::cos(omega * integrator.state().t)}}));
    };
}

void report_swinging_cube(const SwingingCubeSetup& setup, const SwingingCubeResult& result,
                          const std::vector<SwingingCubeError>& history, double wall_time,
                          RunContext& context)
{
    context.count_steps(result.steps);
    auto& history_table = context.table(
        "error_history.dat",
        {{"t", "s", "time"},
         {"error_l2", "1", "normalised L2 displacement error against eq. (53)"},
         {"error_boundary_layer", "1", "the same over the particles within one spacing of a face"},
         {"error_interior", "1", "the same over the other particles"},
         {"mode_amplitude", "1", "projection c(t) of u_a on the mode shape u(X_a, 0) (exact: cos omega t)"},
         {"residual", "1", "sqrt(sum |u_a - c phi_a|^2 / sum |phi_a|^2): the part that is not the mode"}});
    for (const SwingingCubeError& error : history)
        history_table.row(
            {error.t, error.l2, error.boundary_layer, error.interior, error.mode_amplitude, error.residual});
    auto& particles = context.table("particles.dat", {{"X1", "m", "reference position"},
                                                      {"X2", "m", ""},
                                                      {"X3", "m", ""},
                                                      {"von_mises", "Pa", "von Mises stress at t = 0"}});
    for (Eigen::Index a = 0; a < result.X.cols(); ++a)
        particles.row({result.X(0, a), result.X(1, a), result.X(2, a),
                       result.initial_von_mises[static_cast<std::size_t>(a)]});
    auto& summary = context.summary();
    summary["displacement_error_l2"] = result.displacement_error_l2;
    summary["initial_von_mises_error_l2"] =
        result.initial_von_mises_error_l2; // against eq. (53) at X_a (Fig. 4)
    summary["displacement_error_l2_boundary_layer"] = result.error.boundary_layer;
    summary["displacement_error_l2_interior"] = result.error.interior;
    const ModeErrorParts parts = mode_error_parts(setup.cube, result.error);
    summary["displacement_error_mode_part"] = parts.mode;
    summary["displacement_error_other_part"] = parts.other;
    summary["spacing"] = result.spacing;
    summary["particles"] = result.particles;
    summary["dt"] = result.dt;
    summary["dt_over_limit"] =
        result.dt / result.dt_limit; // predicted limit C_stab L_min / c_eff (vsm/stability.hpp)
    summary["omega"] = setup.cube.angular_frequency();
    summary["period"] = 2 * std::numbers::pi / setup.cube.angular_frequency();
    summary["run_wall_time_s"] = wall_time; // reference cells + model setup + time stepping
    summary["cost_per_step_per_particle_s"] =
        wall_time / (static_cast<double>(result.steps) * result.particles);
}

void run_swinging_cube_scene(const SwingingCubeOptions& options, RunContext& context)
{
    const SwingingCubeSetup setup = swinging_cube_setup(options);
    context.record_seed(setup.seed);
    std::vector<SwingingCubeError> history;
    const auto start = std::chrono::steady_clock::now();
    const SwingingCubeResult result = run_swinging_cube(
        setup, [&history](const SwingingCubeError& error) { history.push_back(error); },
        options.history_samples, swinging_cube_frames(setup.cube, context));
    report_swinging_cube(setup, result, history, seconds_since(start), context);
}

} // namespace

Scene swinging_cube_scene()
{
    return bound_scene(
               "vsm.swinging_cube",
               "VSM swinging cube (Frenning Fig. 5): displacement error against the linear solution eq. "
               "(53) at t = 5 ms",
               swinging_cube_binding(), run_swinging_cube_scene)
        .needing(swinging_cube_binding().estimate([](const SwingingCubeOptions& options) {
            return vsm_particle_memory(cube(double(options.setup.per_side)), "particles (per_side^3)");
        }))
        .with_vtk();
}

} // namespace softgrain::vsm
