// Scenes of SPD assemblies (Trivino et al., section 5): spd.bench, spd.compaction.
#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/option_binding.hpp"
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
// spd.bench's options: the assembly and the number of time steps.
struct BenchOptions
{
    AssemblySetup setup;
    long steps = 2000;
};

// The scene's defaults where they differ from the library's.
BenchOptions bench_defaults()
{
    BenchOptions options;
    options.setup.particles = 400;
    options.setup.ring.nodes = 32;
    options.setup.ring.dt_factor = 0.2;
    return options;
}

OptionBinding<BenchOptions> bench_binding()
{
    OptionBinding<BenchOptions> b(bench_defaults());
    b.integer(path(&BenchOptions::setup, &AssemblySetup::particles), "particles", "1", "number of rings")
        .at_least(1);
    b.integer(path(&BenchOptions::setup, &AssemblySetup::ring, &RingSetup::nodes), "nodes", "1",
              "vertices per ring")
        .at_least(8);
    b.count(&BenchOptions::steps, "steps", "1", "time steps (the first is not timed)").at_least(2);
    b.seed(path(&BenchOptions::setup, &AssemblySetup::seed), "seed", "seed of the initial velocities");
    b.real(path(&BenchOptions::setup, &AssemblySetup::ring, &RingSetup::dt_factor), "dt_factor", "1",
           "time step over dt_c = sqrt(m/k_max); below the vertex-pair limit 0.236 "
           "(decision spd-vertex-pair-stability)")
        .positive();
    return b;
}

void run_bench(const BenchOptions& options, RunContext& context)
{
    const AssemblySetup& setup = options.setup;
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
    const long steps = options.steps;
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

OptionBinding<CompactionSetup> compaction_binding()
{
    const auto ring = [](auto... field) {
        return path(&CompactionSetup::assembly, &AssemblySetup::ring, field...);
    };
    OptionBinding<CompactionSetup> b(compaction_scene_defaults());
    b.integer(path(&CompactionSetup::assembly, &AssemblySetup::particles), "particles", "1",
              "number of rings (the paper: 500)")
        .at_least(2);
    b.integer(ring(&RingSetup::nodes), "nodes", "1", "vertices per ring").at_least(8);
    b.real(ring(&RingSetup::material, &ShellMaterial::h), "h", "m",
           "shell thickness (2r = h; mean ring radius R = 1 m)")
        .positive();
    b.real(path(&CompactionSetup::assembly, &AssemblySetup::radius_spread), "radius_spread", "1",
           "Delta R/R, standard deviation of the radii")
        .non_negative()
        .below(0.5);
    b.real(ring(&RingSetup::eta), "eta", "1",
           "core-to-shell stiffness ratio, eq. (24); inf: incompressible core")
        .non_negative()
        .infinity_allowed();
    b.real(ring(&RingSetup::plastic_ratio), "plastic_ratio", "1", "M_b^Y/M*, eq. (32); inf: elastic shells")
        .positive()
        .infinity_allowed();
    b.real(&CompactionSetup::wall_speed, "wall_speed", "R omega_2",
           "top-wall speed over R omega_2 (omega_2: ovalisation frequency of a free ring)")
        .positive();
    b.real(&CompactionSetup::strain_max, "strain_max", "1", "largest vertical strain ln(H0/H)")
        .positive()
        .below(1.0);
    b.real(&CompactionSetup::stress_max, "stress_max", "sigma*",
           "loading also ends when sigma reaches this (incompressible rings jam before eps = ln(V0/V_s))")
        .positive()
        .infinity_allowed();
    b.real(&CompactionSetup::gravity, "gravity", "EI/R^2", "particle weight during the deposition")
        .positive();
    b.real(&CompactionSetup::rest_tolerance, "rest_tolerance", "particle weight",
           "deposition at rest when the largest unbalanced vertex force is below this")
        .positive();
    b.real(ring(&RingSetup::dt_factor), "dt_factor", "1",
           "time step over dt_c = sqrt(m/k_max); stable for a vertex-vertex contact below 0.236 "
           "(decisions spd-compaction-time-step, spd-vertex-pair-stability)")
        .positive();
    b.seed(path(&CompactionSetup::assembly, &AssemblySetup::seed), "seed",
           "seed of the radii and of the deposition");
    b.check([](const CompactionSetup& setup) {
        const RingSetup& ring_setup = setup.assembly.ring;
        if (ring_setup.material.h >= 0.5 * ring_setup.radius)
            throw InputError("h = " + std::to_string(ring_setup.material.h) +
                             ": the shell must be thin against the ring; allowed: h < 0.5 R = 0.5 m");
    });
    return b;
}

// spd.compaction (section 5, Figs. 26-29): deposition under gravity, uniaxial loading to eps = strain_max
// at constant top-wall speed, unloading back to H0 (lib/spd/compaction.hpp).
void run_compaction(const CompactionSetup& setup, RunContext& context)
{
    const RingSetup& ring = setup.assembly.ring;
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
    registry.add(
        bound_scene(
            "spd.bench",
            "SPD speed: elastic rings colliding in a box; vertex-steps per second of the time-step loop",
            bench_binding(), run_bench)
            .needing(rings_memory)
            .without_vtk("a timed scene: writing frames would change the time it measures; "
                         "spd.compaction draws colliding rings"));
    Scene compaction = bound_scene(
        "spd.compaction",
        "SPD section 5: uniaxial compaction and unloading of polydisperse frictionless core-shell "
        "rings deposited under gravity; sigma/sigma*, void ratio, Delta V_s/Delta V, W_i/<W> (Figs. 26-29)",
        compaction_binding(), run_compaction);
    compaction.checkpoints = true;
    registry.add(std::move(compaction).needing(rings_memory).with_vtk());
}

} // namespace softgrain
