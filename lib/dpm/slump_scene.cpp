// dpm.slump: slump test of rough or smooth deformable particles under gravity (DPM Fig. 9.3): the confined
// pile at rest, then the pile at rest after the right wall is removed; run-out, angle of repose from the
// free-surface profile, layers at the front, wall-force balance.
#include "dpm/slump_scene.hpp"

#include "core/fits.hpp"
#include "core/output.hpp"
#include "dpm/slump.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::dpm {

namespace {

struct SurfaceFit
{
    std::vector<double> centre, height; // occupied bins [D]
    double intercept = 0, slope = 0;    // height = intercept + slope centre
};

// Least-squares line through the topmost-vertex heights of the occupied bins of width D (0, 0 below two
// bins).
SurfaceFit fit_surface(const Eigen::VectorXd& x, double diameter)
{
    SurfaceFit fit;
    const std::vector<double> top = surface_profile(x, diameter);
    for (std::size_t k = 0; k < top.size(); ++k)
        if (!std::isnan(top[k])) {
            fit.centre.push_back(k + 0.5);
            fit.height.push_back(top[k] / diameter);
        }
    if (const auto line = fit_line(fit.centre, fit.height)) {
        fit.intercept = line->intercept;
        fit.slope = line->slope;
    }
    return fit;
}

} // namespace

void run_slump_scene(const Parameters& p, RunContext& context)
{
    SlumpOptions o;
    o.interaction = interaction_from_name(p.choice("contact"));
    o.particles = static_cast<int>(p.integer("particles"));
    o.nodes_small = static_cast<int>(p.integer("nodes_small"));
    o.nodes_large = static_cast<int>(p.integer("nodes_large"));
    o.box_width = p.real("box_width");
    o.gravity = p.real("gravity");
    o.wall_friction = p.real("wall_friction");
    o.tangential_stiffness = p.real("tangential_stiffness");
    o.damping = p.real("damping");
    o.rest_tolerance = p.real("rest_tolerance");
    o.max_steps = p.integer("max_steps");
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(o.seed);
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
    const SlumpResult r = run_slump(o, vtk_frame);
    context.count_steps(r.confined.rest.steps + r.released.rest.steps);
    const DpmSystem& s = r.system;
    const double D = r.diameter;

    // Snapshots: each particle's polygon (closed: the first vertex repeated) with its vertex radius.
    auto& snapshots =
        context.table("snapshots.dat", {{"frame", "1", "1 = confined at rest, 2 = released at rest"},
                                        {"particle", "1", "index"},
                                        {"x", "D", "vertex x (left wall at 0)"},
                                        {"y", "D", "vertex y (floor at 0)"},
                                        {"radius", "D", "vertex radius sigma/2"}});
    for (int frame : {1, 2}) {
        const Eigen::VectorXd& x = frame == 1 ? r.confined.x : r.released.x;
        for (std::size_t m = 0; m < s.particles.size(); ++m) {
            const Particle& q = s.particles[m];
            for (int k = 0; k <= q.count; ++k) {
                const int v = q.first + k % q.count;
                snapshots.row({double(frame), double(m), x(2 * v) / D, x(2 * v + 1) / D, 0.5 * q.sigma / D});
            }
        }
    }
    const SurfaceFit fit = fit_surface(r.released.x, D);
    auto& profile =
        context.table("profile.dat", {{"x", "D", "bin centre (bins of width D from the left wall)"},
                                      {"height", "D", "topmost vertex height + sigma/2 in the bin"},
                                      {"fit", "D", "least-squares line through the heights"}});
    for (std::size_t k = 0; k < fit.centre.size(); ++k)
        profile.row({fit.centre[k], fit.height[k], fit.intercept + fit.slope * fit.centre[k]});

    const double front = pile_front(r.released.x);
    double weight = 0;
    for (const Particle& q : s.particles)
        weight += q.count * o.gravity; // unit vertex mass
    auto& summary = context.summary();
    summary["run_out"] = front / D;
    summary["run_out_over_box_width"] = front / r.box_width;
    summary["angle_of_repose"] = std::atan(-fit.slope) * 180 / std::numbers::pi;
    summary["layers_right_edge"] = particles_crossing(s, r.released.x, front - D);
    summary["height_max"] = *std::max_element(fit.height.begin(), fit.height.end());
    summary["height_confined"] = fit_surface(r.confined.x, D).intercept;
    summary["unbalanced_confined"] = r.confined.rest.unbalanced;
    summary["unbalanced_released"] = r.released.rest.unbalanced;
    summary["steps_confined"] = r.confined.rest.steps;
    summary["steps_released"] = r.released.rest.steps;
    summary["dt"] = r.dt;
    summary["diameter"] = D;
    const WallForces& w = r.released.rest.walls;
    summary["floor_force_over_weight"] = w.floor_normal / weight;
    summary["horizontal_wall_force_over_weight"] = (w.left + w.right + w.floor_friction) / weight;
    summary["confined_floor_force_over_weight"] = r.confined.rest.walls.floor_normal / weight;
}

std::vector<ParameterSpec> slump_parameters()
{
    return {
        ParameterSpec::choice("contact", "rough", {"rough", "smooth"},
                              "interaction between particles: rough (eqs. 9.3-9.4) or smooth (eqs. 9.5-9.9)"),
        ParameterSpec::integer("particles", 40, "1",
                               "particles, 50:50 bidisperse, diameter ratio 1.4 (paper: 100)")
            .at_least(2),
        ParameterSpec::integer("nodes_small", 12, "1", "vertices N_mu of the small particles").at_least(6),
        ParameterSpec::integer("nodes_large", 16, "1", "vertices N_mu of the large particles").at_least(6),
        ParameterSpec::real("box_width", 5, "D", "confining box width in mean outer particle diameters D")
            .positive(),
        ParameterSpec::real("gravity", 2e-4, "k_c sigma/m", "gravitational acceleration g (vertex mass m)")
            .positive(),
        ParameterSpec::real("wall_friction", 0.1, "1",
                            "Coulomb coefficient mu_w of the floor's tangential spring")
            .non_negative(),
        ParameterSpec::real("tangential_stiffness", 1, "k_c",
                            "stiffness k_t of the floor's tangential spring")
            .positive(),
        ParameterSpec::real("damping", 2e-3, "sqrt(m k_c)", "viscous damping c of every vertex velocity")
            .positive(),
        ParameterSpec::real("rest_tolerance", 1e-3, "1",
                            "at rest: max unbalanced particle force < tol x weight and vertex speeds < "
                            "tol x sqrt(g sigma)")
            .positive()
            .below(1.0),
        ParameterSpec::integer("max_steps", 2000000, "1", "step cap of each stage (exit 3 beyond)")
            .at_least(1),
        ParameterSpec::seed("seed", 1, "seed of the placement and orientations"),
    };
}

} // namespace softgrain::dpm
