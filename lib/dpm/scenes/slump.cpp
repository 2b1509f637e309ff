// dpm.slump: slump test of rough or smooth deformable particles under gravity (DPM Fig. 9.3): the confined
// pile at rest, then the pile at rest after the right wall is removed; run-out, angle of repose from the
// free-surface profile, layers at the front, wall-force balance.
#include "dpm/scenes/scenes.hpp"

#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/slump.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace softgrain::dpm {

namespace {

OptionBinding<SlumpOptions> slump_binding()
{
    OptionBinding<SlumpOptions> binding;
    binding.choice(&SlumpOptions::interaction, "contact",
                   {{"rough", InteractionKind::rough}, {"smooth", InteractionKind::smooth}},
                   "interaction between particles: rough (eqs. 9.3-9.4) or smooth (eqs. 9.5-9.9)");
    binding
        .integer(&SlumpOptions::particles, "particles", "1",
                 "particles, 50:50 bidisperse, diameter ratio 1.4 (paper: 100)")
        .at_least(2);
    binding.integer(&SlumpOptions::nodes_small, "nodes_small", "1", "vertices N_mu of the small particles")
        .at_least(6);
    binding.integer(&SlumpOptions::nodes_large, "nodes_large", "1", "vertices N_mu of the large particles")
        .at_least(6);
    binding
        .real(&SlumpOptions::box_width, "box_width", "D",
              "confining box width in mean outer particle diameters D")
        .positive();
    binding
        .real(&SlumpOptions::gravity, "gravity", "k_c sigma/m",
              "gravitational acceleration g (vertex mass m)")
        .positive();
    binding
        .real(&SlumpOptions::wall_friction, "wall_friction", "1",
              "Coulomb coefficient mu_w of the floor's tangential spring")
        .non_negative();
    binding
        .real(&SlumpOptions::tangential_stiffness, "tangential_stiffness", "k_c",
              "stiffness k_t of the floor's tangential spring")
        .positive();
    binding
        .real(&SlumpOptions::damping, "damping", "sqrt(m k_c)", "viscous damping c of every vertex velocity")
        .positive();
    binding
        .real(&SlumpOptions::rest_tolerance, "rest_tolerance", "1",
              "at rest: max unbalanced particle force < tol x weight and vertex speeds < tol x sqrt(g sigma)")
        .positive()
        .below(1.0);
    // A long count, bounded as the scene has always declared it (an int's range, ample for a step cap).
    binding.count(&SlumpOptions::max_steps, "max_steps", "1", "step cap of each stage (exit 3 beyond)")
        .at_least(1)
        .at_most(std::numeric_limits<int>::max());
    binding.seed(&SlumpOptions::seed, "seed", "seed of the placement and orientations");
    return binding;
}

void run_slump_scene(const SlumpOptions& options, RunContext& context)
{
    context.record_seed(options.seed);
    // ParaView frames every 2000 time steps (--vtk-every N: every N steps), from the start through both
    // stages, the simulation time step * dt as time value: the particles with their vertex velocities and
    // the walls (floor, left wall, and the right wall until it is removed) and the contacts between
    // particles.
    const auto vtk_frame = [&](const DpmSystem& system, const SlumpWorld& world, const Eigen::VectorXd& x,
                               const Eigen::VectorXd& v, long step, double time) {
        if (!context.vtk() || !context.vtk()->due(step, 2000)) return;
        vtk::PolyData particles = dpm_particles(system, x);
        std::vector<double> velocity;
        for (Eigen::Index k = 0; k < v.size(); k += 2)
            velocity.insert(velocity.end(), {v(k), v(k + 1), 0.0});
        particles.point_vectors("velocity", std::move(velocity));
        double top = 0, right = 0;
        for (Eigen::Index k = 0; k < x.size(); k += 2)
            top = std::max(top, x(k + 1)), right = std::max(right, x(k));
        vtk::PolyData walls;
        const double height = top + 1, reach = std::isfinite(world.right_wall) ? world.right_wall : right + 1;
        walls.add_line({walls.add_point(0, 0), walls.add_point(reach, 0)});
        walls.add_line({walls.add_point(0, 0), walls.add_point(0, height)});
        std::vector<std::int64_t> ids{0, 1};
        if (std::isfinite(world.right_wall)) {
            walls.add_line({walls.add_point(world.right_wall, 0), walls.add_point(world.right_wall, height)});
            ids.push_back(2);
        }
        walls.cell_ids("wall_id", std::move(ids)); // 0 floor, 1 left, 2 right
        std::vector<vtk::Part> parts{{"particles", std::move(particles)},
                                     {"walls", std::move(walls)},
                                     {"contacts", dpm_contacts(system, x)}};
        for (auto& part : parts) {
            part.data.field("step", static_cast<double>(step));
            part.data.field("released", std::isfinite(world.right_wall) ? 0.0 : 1.0);
        }
        context.vtk()->write(time, parts);
    };
    const SlumpResult result = run_slump(options, vtk_frame);
    context.count_steps(result.confined.rest.steps + result.released.rest.steps);
    const DpmSystem& system = result.system;
    const double D = result.diameter;

    // Snapshots: each particle's polygon (closed: the first vertex repeated) with its vertex radius.
    auto& snapshots =
        context.table("snapshots.dat", {{"frame", "1", "1 = confined at rest, 2 = released at rest"},
                                        {"particle", "1", "index"},
                                        {"x", "D", "vertex x (left wall at 0)"},
                                        {"y", "D", "vertex y (floor at 0)"},
                                        {"radius", "D", "vertex radius sigma/2"}});
    for (int frame : {1, 2}) {
        const Eigen::VectorXd& x = frame == 1 ? result.confined.x : result.released.x;
        for (std::size_t m = 0; m < system.particles.size(); ++m) {
            const Particle& particle = system.particles[m];
            for (int k = 0; k <= particle.count; ++k) {
                const int v = particle.first + k % particle.count;
                snapshots.row(
                    {double(frame), double(m), x(2 * v) / D, x(2 * v + 1) / D, 0.5 * particle.sigma / D});
            }
        }
    }
    const SurfaceFit fit = fit_free_surface(result.released.x, D);
    auto& profile =
        context.table("profile.dat", {{"x", "D", "bin centre (bins of width D from the left wall)"},
                                      {"height", "D", "topmost vertex height + sigma/2 in the bin"},
                                      {"fit", "D", "least-squares line through the heights"}});
    for (std::size_t k = 0; k < fit.centre.size(); ++k)
        profile.row({fit.centre[k], fit.height[k], fit.intercept + fit.slope * fit.centre[k]});

    const double front = pile_front(result.released.x);
    double weight = 0;
    for (const Particle& particle : system.particles)
        weight += particle.count * options.gravity; // unit vertex mass
    auto& summary = context.summary();
    summary["run_out"] = front / D;
    summary["run_out_over_box_width"] = front / result.box_width;
    summary["angle_of_repose"] = std::atan(-fit.slope) * 180 / std::numbers::pi;
    summary["layers_right_edge"] = particles_crossing(system, result.released.x, front - D);
    summary["height_max"] = *std::max_element(fit.height.begin(), fit.height.end());
    summary["height_confined"] = fit_free_surface(result.confined.x, D).intercept;
    summary["unbalanced_confined"] = result.confined.rest.unbalanced;
    summary["unbalanced_released"] = result.released.rest.unbalanced;
    summary["steps_confined"] = result.confined.rest.steps;
    summary["steps_released"] = result.released.rest.steps;
    summary["dt"] = result.dt;
    summary["diameter"] = D;
    const WallForces& walls = result.released.rest.walls;
    summary["floor_force_over_weight"] = walls.floor_normal / weight;
    summary["horizontal_wall_force_over_weight"] = (walls.left + walls.right + walls.floor_friction) / weight;
    summary["confined_floor_force_over_weight"] = result.confined.rest.walls.floor_normal / weight;
}

} // namespace

Scene slump_scene()
{
    return bound_scene(
               "dpm.slump",
               "DPM Fig. 9.3: slump test of rough or smooth deformable particles under gravity, right "
               "wall removed; run-out, angle of repose, layers at the front",
               slump_binding(), run_slump_scene)
        .needing(slump_binding().estimate([](const SlumpOptions& options) {
            return bidisperse_memory({options.particles, options.nodes_small, options.nodes_large, false});
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
