// Scenes of SPD assemblies (Trivino et al., section 5): spd.bench, spd.compaction.
#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/output.hpp"
#include "core/rng.hpp"
#include "spd/assembly.hpp"
#include "spd/compaction.hpp"
#include "spd/shell_model.hpp"
#include "spd/spd_scenes.hpp"
#include "spd/vtk_frames.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace softgrain {

namespace {
using namespace spd;

// spd.bench: `particles` elastic rings (eta = 0) of `nodes` vertices, touching on a square lattice in a box,
// each launched with a random rigid velocity of 0.02 r per time step (r the vertex radius), `steps`
// undamped-in-the-bulk velocity-Verlet steps (contact damping only): rings collide, bend and rearrange,
// the neighbour list is rebuilt every few tens of steps. Reports vertex-steps per second of the step loop.
void run_bench(const Parameters& p, RunContext& context)
{
    AssemblySetup setup;
    setup.particles = static_cast<int>(p.integer("particles"));
    setup.ring.nodes = static_cast<int>(p.integer("nodes"));
    setup.seed = static_cast<std::uint64_t>(p.integer("seed"));
    setup.ring.dt_factor = p.real("dt_factor");
    context.record_seed(setup.seed);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(setup.particles))));
    Assembly a = rings_in_box(setup, columns);
    const double dt = setup.ring.dt_factor * a.model.critical_time_step();
    a.model.check_time_step(dt);
    const double speed = 0.02 * ring_scales(setup.ring).radius_vertex / dt;
    // A dt_factor so small that the launch speed 0.02 r/dt overflows (4.9e-324 aborted the run).
    if (!std::isfinite(speed))
        throw InputError(
            "'dt_factor' = " + number_text(setup.ring.dt_factor) + " gives dt = " + number_text(dt) +
            " s and a launch speed 0.02 r/dt that is not finite; allowed: dt_factor with a finite "
            "launch speed");
    Rng rng(setup.seed + 1);
    for (int shell : a.particles) {
        const double angle = rng.uniform(0, 2 * std::numbers::pi);
        a.model.set_velocity(shell, speed * Vec2(std::cos(angle), std::sin(angle)));
    }
    const long steps = p.integer("steps");
    a.model.step(dt, 0.0); // first force evaluation and list build outside the timing
    const auto start = std::chrono::steady_clock::now();
    for (long n = 1; n < steps; ++n)
        a.model.step(dt, 0.0);
    const double seconds = seconds_since(start);
    context.count_steps(steps);
    const int vertices = particle_vertices(a);
    auto& s = context.summary();
    s["vertex_steps_per_second"] = vertices * static_cast<double>(steps - 1) / seconds;
    s["vertices"] = vertices;
    s["threads"] = omp_get_max_threads();
    s["loop_seconds"] = seconds;
    s["contact_candidates_per_vertex"] = static_cast<double>(a.model.contact_candidates()) / vertices;
    s["neighbour_list_builds"] = a.model.neighbour_list_builds();
    s["kinetic_energy_final"] = a.model.kinetic_energy();
    // The assembly's geometry and laws, for an equivalent run in another code (scripts/bench-vs-lammps).
    const RingScales sc = ring_scales(setup.ring);
    s["ring_radius"] = setup.ring.radius;
    s["vertex_radius"] = sc.radius_vertex;
    s["vertex_mass"] = setup.ring.vertex_mass;
    s["k_s"] = sc.laws.k_s;
    s["k_b"] = sc.laws.k_b;
    s["k_n"] = sc.laws.k_s; // contact stiffness of the ring scenes (rings_in_box)
    s["dt"] = dt;
    s["box_width"] = a.width;
    s["box_height"] = a.height;
    s["columns"] = columns;
    s["speed"] = speed;
    s["neighbour_skin"] = a.model.neighbour_skin();
}

// spd.compaction (section 5, Figs. 26-29): deposition under gravity, uniaxial loading to eps = strain_max
// at constant top-wall speed, unloading back to H0 (lib/spd/compaction.hpp).
void run_compaction(const Parameters& p, RunContext& context)
{
    CompactionSetup setup;
    setup.assembly.particles = static_cast<int>(p.integer("particles"));
    setup.assembly.radius_spread = p.real("radius_spread");
    setup.assembly.seed = static_cast<std::uint64_t>(p.integer("seed"));
    RingSetup& ring = setup.assembly.ring;
    ring.nodes = static_cast<int>(p.integer("nodes"));
    ring.material.h = p.real("h");
    ring.eta = p.real("eta");
    ring.plastic_ratio = p.real("plastic_ratio");
    setup.gravity = p.real("gravity");
    setup.rest_tolerance = p.real("rest_tolerance");
    setup.wall_speed = p.real("wall_speed");
    setup.strain_max = p.real("strain_max");
    setup.stress_max = p.real("stress_max");
    ring.dt_factor = p.real("dt_factor");
    if (ring.material.h >= 0.5 * ring.radius)
        throw InputError("h = " + std::to_string(ring.material.h) +
                         ": the shell must be thin against the ring; allowed: h < 0.5 R = 0.5 m");
    context.record_seed(setup.assembly.seed);
    const RingScales sc = ring_scales(ring);
    const double R = ring.radius, s_depth = ring.material.s, sigma_star = sc.characteristic.sigma_star;
    auto progress = context.progress("spd.compaction");
    // ParaView frames at the recorded states (`records` per half cycle), the time since the top wall
    // started to move as the time value.
    const auto frame = [&](const Assembly& a, const CompactionState& st) {
        if (context.vtk() && context.vtk()->next())
            context.vtk()->write(
                st.time,
                shell_frame(
                    a.model, a.particles, {a.bottom, a.top, a.left, a.right},
                    {{"strain", st.strain}, {"height", st.height}, {"loading", st.loading ? 1.0 : 0.0}}));
    };
    const CompactionResult r = compaction(
        setup, frame, [&](double f) { progress.update(f); }, context.checkpoints());
    // Quasi-static check: largest |F_top - F_bottom| over the loading, relative to the largest top force.
    double mismatch = 0, force_max = 0;
    for (const CompactionState& st : r.states)
        if (st.loading) {
            mismatch = std::max(mismatch, std::abs(st.force_top - st.force_bottom));
            force_max = std::max(force_max, st.force_top);
        }
    mismatch /= force_max;
    progress.finish();
    context.count_steps(r.steps); // the model counts the deposit steps too
    const double W = r.width, A0 = r.solid_area0;
    const auto void_ratio = [&](const CompactionState& st) {
        return (W * st.height - st.solid_area) / st.solid_area;
    };
    const auto volume_share = [&](const CompactionState& st) {
        return st.height < r.height0 ? (A0 - st.solid_area) / (W * (r.height0 - st.height)) : NAN;
    };
    auto& table = context.table(
        "compaction.dat",
        {{"eps", "1", "vertical strain ln(H0/H)"},
         {"loading", "1", "1 loading, 0 unloading"},
         {"H_over_R", "1", "sample height over the mean radius"},
         {"sigma_over_sigmastar", "1", "top-wall stress F_top/(W s) over sigma* = F*/(2Rs), eq. (37)"},
         {"sigma_bottom_over_sigmastar", "1", "bottom-wall stress over sigma*"},
         {"e", "1", "void ratio V_r/V_s (V_s: shells dilated by r)"},
         {"dVs_over_dV", "1", "particle share of the volume change (V_s0 - V_s)/(V0 - V)"},
         {"kinetic_over_weightR", "1", "kinetic energy over the deposition weight times R"}});
    const CompactionState* end_of_loading = nullptr;
    double residual_strain = NAN, dVs_peak = 0, sigma_max = 0;
    for (const CompactionState& st : r.states) {
        table.row({st.strain, st.loading ? 1.0 : 0.0, st.height / R,
                   st.force_top / (W * s_depth) / sigma_star, st.force_bottom / (W * s_depth) / sigma_star,
                   void_ratio(st), volume_share(st), st.kinetic_energy / (r.deposit.weight * R)});
        if (st.loading) {
            end_of_loading = &st;
            sigma_max = std::max(sigma_max, st.force_top / (W * s_depth) / sigma_star);
            if (std::isfinite(volume_share(st)) && st.strain >= 0.05)
                dVs_peak = std::max(dVs_peak, volume_share(st));
        } else if (std::isnan(residual_strain) && st.force_top <= 0) {
            residual_strain = st.strain; // the top wall leaves the sample
        }
    }
    // Eq. (38): e = e0 - C log10(sigma/sigma*) over the last two decades of stress of the loading.
    std::vector<double> log_sigma, e_fit;
    for (const CompactionState& st : r.states) {
        const double sigma = st.force_top / (W * s_depth) / sigma_star;
        if (st.loading && sigma >= 0.01 * sigma_max) {
            log_sigma.push_back(std::log10(sigma));
            e_fit.push_back(void_ratio(st));
        }
    }
    const std::optional<Line> compressibility = fit_line(log_sigma, e_fit);
    auto& snapshot = context.table(
        "snapshot.dat",
        {{"snapshot", "1", "0: first contact of the top wall (H0), ..., last: end of loading (Figs. 26, 29)"},
         {"eps", "1", "ln(H0/H) of the snapshot"},
         {"H_over_R", "1", "top-wall height over the mean radius"},
         {"particle", "1", "particle index"},
         {"x_over_R", "1", "vertex position over the mean radius (closed polygon)"},
         {"y_over_R", "1", "vertex position"},
         {"W_over_mean", "1", "elastic energy W_i of the particle over <W> of the snapshot (Fig. 29)"}});
    for (std::size_t n = 0; n < r.snapshots.size(); ++n) {
        const CompactionSnapshot& snap = r.snapshots[n];
        double W_mean = 0;
        for (double w : snap.energy)
            W_mean += w / static_cast<double>(snap.energy.size());
        for (std::size_t i = 0; i < snap.particles.size(); ++i)
            for (std::size_t k = 0; k <= snap.particles[i].size(); ++k) {
                const Vec2& x = snap.particles[i][k % snap.particles[i].size()];
                // NaN only if no ring is deformed at all (W_mean = 0).
                snapshot.row({double(n), snap.strain, snap.height / R, double(i), x.x() / R, x.y() / R,
                              W_mean > 0 ? snap.energy[i] / W_mean : NAN});
            }
    }
    auto& s = context.summary();
    const CompactionState& first = r.states.front();
    const CompactionState& last = r.states.back();
    s["e0"] = void_ratio(first);
    s["e_at_strain_max"] = void_ratio(*end_of_loading);
    s["e_after_unloading"] = void_ratio(last);
    s["strain_at_max"] = end_of_loading->strain;
    s["sigma_over_sigmastar_max"] = sigma_max;
    s["compressibility_index"] =
        compressibility ? nlohmann::json(-compressibility->slope) : nlohmann::json(nullptr);
    s["compressibility_fit_e0"] =
        compressibility ? nlohmann::json(compressibility->intercept) : nlohmann::json(nullptr);
    s["compressibility_fit_points"] = log_sigma.size();
    s["dVs_over_dV_at_strain_max"] = finite_or_null(volume_share(*end_of_loading));
    s["dVs_over_dV_peak"] = dVs_peak;
    s["residual_strain"] = finite_or_null(residual_strain);
    s["wall_force_mismatch_max"] = mismatch;
    s["deposit_bottom_force_over_weight"] =
        r.deposit.bottom_force / (r.deposit.weight * setup.assembly.particles);
    s["deposit_residual_over_particle_weight"] = r.deposit.residual_force / r.deposit.weight;
    s["deposit_steps"] = r.deposit.steps;
    s["disk_fire_iterations"] = r.deposit.disks.iterations;
    s["H0_over_R"] = r.height0 / R;
    s["W_over_R"] = W / R;
    s["vertices"] = particle_vertices(r.deposit.assembly);
    s["sigma_star"] = sigma_star;
    s["wall_speed_m_per_s"] = r.wall_speed;
    s["dt"] = r.dt;
    s["compaction_steps"] = r.steps - r.deposit.steps;
}

} // namespace

void register_spd_assembly_scenes(SceneRegistry& registry)
{
    const auto rings_memory = [](const Parameters& p) {
        return spd::shell_model_memory(double(p.integer("particles")) * double(p.integer("nodes")),
                                       "vertices (particles x nodes)");
    };
    registry.add(Scene{
        "spd.bench",
        "SPD speed: elastic rings colliding in a box; vertex-steps per second of the time-step loop",
        {
            ParameterSpec::integer("particles", 400, "1", "number of rings").at_least(1),
            ParameterSpec::integer("nodes", 32, "1", "vertices per ring").at_least(8),
            ParameterSpec::integer("steps", 2000, "1", "time steps (the first is not timed)").at_least(2),
            ParameterSpec::seed("seed", 1, "seed of the initial velocities"),
            ParameterSpec::real("dt_factor", 0.2, "1",
                                "time step over dt_c = sqrt(m/k_max); below the vertex-pair limit 0.236 "
                                "(decision spd-vertex-pair-stability)")
                .positive(),
        },
        run_bench}
                     .needing(rings_memory)
                     .without_vtk("a timed scene: writing frames would change the time it measures; "
                                  "spd.compaction draws colliding rings"));
    registry.add(Scene{
        "spd.compaction",
        "SPD section 5: uniaxial compaction and unloading of polydisperse frictionless core-shell rings "
        "deposited under gravity; sigma/sigma*, void ratio, Delta V_s/Delta V, W_i/<W> (Figs. 26-29)",
        {
            ParameterSpec::integer("particles", 40, "1", "number of rings (the paper: 500)").at_least(2),
            ParameterSpec::integer("nodes", 16, "1", "vertices per ring").at_least(8),
            ParameterSpec::real("h", 0.1, "m", "shell thickness (2r = h; mean ring radius R = 1 m)")
                .positive(),
            ParameterSpec::real("radius_spread", 0.15, "1", "Delta R/R, standard deviation of the radii")
                .non_negative()
                .below(0.5),
            ParameterSpec::real("eta", 0.0, "1",
                                "core-to-shell stiffness ratio, eq. (24); inf: incompressible core")
                .non_negative()
                .infinity_allowed(),
            ParameterSpec::real("plastic_ratio", INFINITY, "1", "M_b^Y/M*, eq. (32); inf: elastic shells")
                .positive()
                .infinity_allowed(),
            ParameterSpec::real(
                "wall_speed", 1e-3, "R omega_2",
                "top-wall speed over R omega_2 (omega_2: ovalisation frequency of a free ring)")
                .positive(),
            ParameterSpec::real("strain_max", 0.3, "1", "largest vertical strain ln(H0/H)")
                .positive()
                .below(1.0),
            ParameterSpec::real("stress_max", 50.0, "sigma*",
                                "loading also ends when sigma reaches this (incompressible rings jam before "
                                "eps = ln(V0/V_s))")
                .positive()
                .infinity_allowed(),
            ParameterSpec::real("gravity", 1e-2, "EI/R^2", "particle weight during the deposition")
                .positive(),
            ParameterSpec::real("rest_tolerance", 1e-2, "particle weight",
                                "deposition at rest when the largest unbalanced vertex force is below this")
                .positive(),
            ParameterSpec::real(
                "dt_factor", 0.2, "1",
                "time step over dt_c = sqrt(m/k_max); stable for a vertex-vertex contact below 0.236 "
                "(decisions spd-compaction-time-step, spd-vertex-pair-stability)")
                .positive(),
            ParameterSpec::seed("seed", 1, "seed of the radii and of the deposition"),
        },
        run_compaction,
        /*checkpoints=*/true}
                     .needing(rings_memory)
                     .with_vtk());
}

} // namespace softgrain
