// vsm.lblock: the free L-shaped block of VSM (Frenning 2022, Figs. 6-8) under a traction pulse: linear and
// angular momentum after the load.
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "vsm/l_block.hpp"
#include "vsm/scenes/parameters.hpp"
#include "vsm/scenes/scenes.hpp"
#include "vsm/vtk_frames.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace softgrain::vsm {

namespace {

// The setup of the library with the one `xi` of both contact factors of eq. (50).
struct LBlockOptions
{
    LBlockSetup setup;
    double xi = 1.0;
};

OptionBinding<LBlockOptions> lblock_binding()
{
    const auto setup = [](auto field) { return path(&LBlockOptions::setup, field); };
    const auto load = [](int component) {
        return [component](LBlockOptions& options) -> double& { return options.setup.load(component); };
    };
    OptionBinding<LBlockOptions> binding;
    binding
        .real(setup(&LBlockSetup::spacing), "spacing", "m",
              "regular lattice spacing (must divide 6, 10 and 3 m)")
        .positive();
    bind_internal_force(binding, path(&LBlockOptions::setup, &LBlockSetup::options, &ModelOptions::internal));
    bind_material(binding, setup(&LBlockSetup::material));
    bind_contact_factor(binding, &LBlockOptions::xi);
    binding.real(load(0), "load_1", "Pa", "component 1 of the traction vector times p(t)");
    binding.real(load(1), "load_2", "Pa", "component 2");
    binding.real(load(2), "load_3", "Pa", "component 3 (printed 900; 450 in related papers)");
    binding.real(setup(&LBlockSetup::end_time), "end_time", "s", "duration (load acts for 5 s)").positive();
    binding.real(setup(&LBlockSetup::cfl), "cfl", "1", "time step dt = cfl L_min / c_p")
        .positive()
        .at_most(2.0);
    bind_time_step_check(binding, setup(&LBlockSetup::time_step_check));
    binding.check([](const LBlockOptions& options) {
        if (options.setup.end_time <= 5.0)
            throw InputError("end_time = " + std::to_string(options.setup.end_time) +
                             " must exceed 5 s (the load)");
    });
    return binding;
}

// The shape of the block at one time of Figs. 6-7.
struct LBlockShape
{
    double t = 0;
    Points<3> x;
};

// What the scene records while the block moves: the momenta every 10 time steps and the shapes at the first
// of those steps at or after each of `shape_times`.
struct LBlockRecord
{
    std::vector<double> shape_times{0, 5, 10, 20, 35, 55};
    std::vector<LBlockSample> momenta;
    std::vector<LBlockShape> shapes;

    void observe(const LBlockSample& sample, const Points<3>& x)
    {
        momenta.push_back(sample);
        if (shapes.size() < shape_times.size() && sample.t >= shape_times[shapes.size()] - 1e-9)
            shapes.push_back({sample.t, x});
    }
};

// ParaView frames every 50 time steps (--vtk-every N: every N steps), time value t [s]; field data
// traction_pulse p(t) of the load.
StepObserver lblock_frames(RunContext& context)
{
    if (!context.vtk()) return {};
    return [&context](const Model& model, const Leapfrog& integrator) {
        if (context.vtk()->due(integrator.state().step, 50))
            context.vtk()->write(
                integrator.state().t,
                vsm_frame(model, integrator, {{"traction_pulse", l_block_pulse(integrator.state().t)}}));
    };
}

void report_lblock(const LBlockSetup& setup, const LBlockResult& result, const LBlockRecord& record,
                   double wall_time, RunContext& context)
{
    context.count_steps(result.steps);
    auto& momentum =
        context.table("momentum.dat", {{"t", "s", "time"},
                                       {"p1", "kg m/s", "linear momentum sum m v, component 1"},
                                       {"p2", "kg m/s", "component 2"},
                                       {"p3", "kg m/s", "component 3"},
                                       {"l1", "kg m^2/s", "angular momentum about the origin, 1"},
                                       {"l2", "kg m^2/s", "component 2"},
                                       {"l3", "kg m^2/s", "component 3"}});
    for (const LBlockSample& sample : record.momenta)
        momentum.row({sample.t, sample.linear.x(), sample.linear.y(), sample.linear.z(), sample.angular.x(),
                      sample.angular.y(), sample.angular.z()});
    auto& shapes = context.table("shapes.dat", {{"t", "s", "time of the snapshot"},
                                                {"x1", "m", "current position"},
                                                {"x2", "m", ""},
                                                {"x3", "m", ""}});
    for (const LBlockShape& shape : record.shapes)
        for (Eigen::Index a = 0; a < shape.x.cols(); ++a)
            shapes.row({shape.t, shape.x(0, a), shape.x(1, a), shape.x(2, a)});
    auto& summary = context.summary();
    summary["internal_force_id"] = setup.options.internal == InternalForce::eq43 ? 43 : 41;
    summary["linear_momentum_drift"] = result.linear_momentum_drift;
    summary["linear_momentum_drift_relative"] = result.linear_momentum_drift / result.impulse_scale;
    summary["angular_momentum_drift_after_load"] = result.angular_momentum_drift_after_load;
    summary["angular_momentum_after_load"] = result.angular_momentum_after_load.norm();
    // Not applicable when the load leaves no angular momentum (a zero traction): the ratio would be 0/0.
    const double angular_momentum = result.angular_momentum_after_load.norm();
    summary["angular_momentum_drift_after_load_relative"] =
        angular_momentum > 0 ? nlohmann::json(result.angular_momentum_drift_after_load / angular_momentum)
                             : nlohmann::json(nullptr);
    summary["impulse_scale"] = result.impulse_scale;
    summary["particles"] = result.particles;
    summary["dt"] = result.dt;
    summary["cost_per_step_per_particle_s"] =
        wall_time / (static_cast<double>(result.steps) * result.particles);
}

void run_lblock(const LBlockOptions& options, RunContext& context)
{
    LBlockSetup setup = options.setup;
    setup.options = with_contact_factors(setup.options, options.xi);
    LBlockRecord record;
    auto progress = context.progress("vsm.lblock");
    const auto observe = [&](const LBlockSample& sample, const Points<3>& x) {
        record.observe(sample, x);
        progress.update(sample.t / setup.end_time);
    };
    const auto start = std::chrono::steady_clock::now();
    const LBlockResult result = run_l_block(setup, 10, observe, lblock_frames(context));
    const double wall_time = seconds_since(start);
    progress.finish();
    report_lblock(setup, result, record, wall_time, context);
}

} // namespace

Scene lblock_scene()
{
    return bound_scene(
               "vsm.lblock",
               "VSM L-shaped block (Frenning Figs. 6-8): free block, traction pulse, momentum conservation",
               lblock_binding(), run_lblock)
        .needing(lblock_binding().estimate([](const LBlockOptions& options) {
            // The L of arms 6 x 3 x 3 m and 3 x 7 x 3 m: 117 m^3.
            return vsm_particle_memory(117.0 / cube(options.setup.spacing),
                                       "particles (117 m^3 / spacing^3)");
        }))
        .with_vtk();
}

} // namespace softgrain::vsm
