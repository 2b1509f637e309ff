// vsm.punch: the punch test of VSM (Frenning 2022, Figs. 9-10): a rigid punch on the middle third of the top
// face, the stabilisation xi and the pressure field.
#include "vsm/punch.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "vsm/scenes/parameters.hpp"
#include "vsm/scenes/scenes.hpp"
#include "vsm/vtk_frames.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace softgrain::vsm {

namespace {

enum class PunchArrangement { regular, irregular };

// The setup of the library with the specimen counted as the scene counts it (per_side over the height,
// 2 per_side - 1 over the width), the jitter of an irregular arrangement, the one `xi` of both contact
// factors of eq. (50) and the final strain.
struct PunchOptions
{
    PunchSetup setup;
    int per_side = 11;
    int layers = 3;
    PunchArrangement arrangement = PunchArrangement::regular;
    double jitter = 0.2;
    double xi = 1.0;
    double final_strain = 0.3;
};

// The library's setup at these options: snapshots at half the final strain and at the end.
PunchSetup punch_setup(const PunchOptions& options)
{
    PunchSetup setup = options.setup;
    setup.counts = {2 * options.per_side - 1, options.per_side, options.layers};
    setup.jitter = options.arrangement == PunchArrangement::irregular ? options.jitter : 0.0;
    setup.options = with_contact_factors(setup.options, options.xi);
    setup.snapshot_strains = {0.5 * options.final_strain, options.final_strain};
    return setup;
}

void require_width_in_thirds(const PunchOptions& options)
{
    const int per_side = options.per_side;
    if ((2 * per_side - 1) % 3 != 0)
        throw InputError(
            "per_side = " + std::to_string(per_side) +
            " gives 2 per_side - 1 particles across the width, which must be divisible by 3 (the "
            "punch covers the middle third): use 2, 5, 8, 11, 14, ...");
}

OptionBinding<PunchOptions> punch_binding()
{
    const auto setup = [](auto field) { return path(&PunchOptions::setup, field); };
    OptionBinding<PunchOptions> binding;
    binding
        .integer(&PunchOptions::per_side, "per_side", "1",
                 "particles over the height; (2 per_side - 1) over the width (21 x 11 in the paper)")
        .at_least(2);
    binding.integer(&PunchOptions::layers, "layers", "1", "particles over the thickness").at_least(1);
    binding.choice(&PunchOptions::arrangement, "arrangement",
                   {{"regular", PunchArrangement::regular}, {"irregular", PunchArrangement::irregular}},
                   "regular cell-centred lattice, or jittered by `jitter` of the spacing");
    binding.real(&PunchOptions::jitter, "jitter", "1", "irregular arrangement: jitter fraction")
        .non_negative()
        .below(0.5);
    bind_jitter_seed(binding, setup(&PunchSetup::seed));
    bind_material(binding, setup(&PunchSetup::material));
    bind_contact_factor(binding, &PunchOptions::xi,
                        "contact (stabilisation) factors xi_n = xi_t of eq. (50)");
    const auto model_options = [](auto field) {
        return path(&PunchOptions::setup, &PunchSetup::options, field);
    };
    binding.real(model_options(&ModelOptions::c1), "c1", "1", "artificial viscosity, linear term of eq. (51)")
        .non_negative();
    binding
        .real(model_options(&ModelOptions::c2), "c2", "1", "artificial viscosity, quadratic term of eq. (51)")
        .non_negative();
    bind_internal_force(binding, model_options(&ModelOptions::internal));
    binding.real(setup(&PunchSetup::punch_velocity), "punch_velocity", "m/s", "downward punch velocity")
        .positive();
    binding
        .real(&PunchOptions::final_strain, "final_strain", "1",
              "punch displacement / height at the end; snapshots at half and at the end")
        .positive()
        .below(1.0);
    binding.real(setup(&PunchSetup::cfl), "cfl", "1", "time step dt = cfl L_min / c_p")
        .positive()
        .at_most(2.0);
    bind_time_step_check(binding, setup(&PunchSetup::time_step_check));
    binding.check(require_width_in_thirds);
    return binding;
}

// ParaView frames every 100 time steps (--vtk-every N: every N steps), time value t [s]: the particles
// (pressure as in Fig. 10) and the walls, the punch moving down; field data punch_displacement v t [m] and
// strain v t / height.
StepObserver punch_frames(double punch_velocity, RunContext& context)
{
    if (!context.vtk()) return {};
    return [punch_velocity, &context](const Model& model, const Leapfrog& integrator) {
        if (!context.vtk()->due(integrator.state().step, 100)) return;
        const double displacement = punch_velocity * integrator.state().t;
        context.vtk()->write(integrator.state().t,
                             vsm_frame(model, integrator,
                                       {{"punch_displacement", displacement},
                                        {"strain", displacement / model.domain().high.y()}}));
    };
}

void report_punch(const PunchSetup& setup, const PunchResult& result, double wall_time, RunContext& context)
{
    context.count_steps(result.steps);
    auto& table = context.table("snapshots.dat", {{"strain", "1", "punch displacement / height"},
                                                  {"x1", "m", "current position"},
                                                  {"x2", "m", ""},
                                                  {"x3", "m", ""},
                                                  {"pressure", "Pa", "Cauchy pressure -tr(sigma)/3"}});
    auto& summary = context.summary();
    const char* tags[] = {"half", "final"};
    for (std::size_t k = 0; k < result.snapshots.size(); ++k) {
        const PunchSnapshot& snapshot = result.snapshots[k];
        for (Eigen::Index a = 0; a < snapshot.x.cols(); ++a)
            table.row({snapshot.strain, snapshot.x(0, a), snapshot.x(1, a), snapshot.x(2, a),
                       snapshot.pressure[static_cast<std::size_t>(a)]});
        const std::string tag = tags[k];
        summary["punch_force_" + tag] = snapshot.punch_force;
        summary["punch_load_total_" + tag] = snapshot.punch_load_total;
        summary["nonaffine_ratio_" + tag] = snapshot.nonaffine_ratio;
        summary["pressure_roughness_" + tag] = snapshot.pressure_roughness;
        summary["pressure_max_" + tag] =
            *std::max_element(snapshot.pressure.begin(), snapshot.pressure.end());
    }
    summary["jitter"] = setup.jitter; // effective: 0 for the regular arrangement
    summary["particles"] = result.particles;
    summary["dt"] = result.dt;
    summary["dt_over_limit"] =
        result.dt / result.dt_limit; // predicted limit C_stab L_min / c_eff (vsm/stability.hpp)
    summary["cost_per_step_per_particle_s"] =
        wall_time / (static_cast<double>(result.steps) * result.particles);
}

void run_punch_scene(const PunchOptions& options, RunContext& context)
{
    const PunchSetup setup = punch_setup(options);
    context.record_seed(setup.seed);
    const auto start = std::chrono::steady_clock::now();
    const PunchResult result = run_punch(setup, {}, punch_frames(setup.punch_velocity, context));
    report_punch(setup, result, seconds_since(start), context);
}

} // namespace

Scene punch_scene()
{
    return bound_scene(
               "vsm.punch",
               "VSM punch test (Frenning Figs. 9-10): rigid punch on the middle third, stabilisation xi, "
               "pressure field",
               punch_binding(), run_punch_scene)
        .needing(punch_binding().estimate([](const PunchOptions& options) {
            const double per_side = double(options.per_side);
            return vsm_particle_memory(per_side * (2 * per_side - 1) * double(options.layers),
                                       "particles (per_side x (2 per_side - 1) x layers)");
        }))
        .with_vtk();
}

} // namespace softgrain::vsm
