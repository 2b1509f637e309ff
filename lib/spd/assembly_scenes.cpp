// Scenes of SPD assemblies (Trivino et al., section 5): spd.bench, spd.compaction.
#include "core/errors.hpp"
#include "core/output.hpp"
#include "core/rng.hpp"
#include "spd/assembly.hpp"
#include "spd/compaction.hpp"
#include "spd/spd_scenes.hpp"

#include <omp.h>

#include <gsl/gsl_fit.h>

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
void run_bench(const Parameters& p, RunContext& ctx)
{
    AssemblySetup setup;
    setup.particles = static_cast<int>(p.integer("particles"));
    setup.ring.nodes = static_cast<int>(p.integer("nodes"));
    setup.seed = static_cast<std::uint64_t>(p.integer("seed"));
    ctx.record_seed(setup.seed);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(setup.particles))));
    Assembly a = rings_in_box(setup, columns);
    const double dt = setup.ring.dt_factor * a.model.critical_time_step();
    a.model.check_time_step(dt);
    const double speed = 0.02 * ring_scales(setup.ring).radius_vertex / dt;
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
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ctx.count_steps(steps);
    const int vertices = particle_vertices(a);
    auto& s = ctx.summary();
    s["vertex_steps_per_second"] = vertices * static_cast<double>(steps - 1) / seconds;
    s["vertices"] = vertices;
    s["threads"] = omp_get_max_threads();
    s["loop_seconds"] = seconds;
    s["contact_candidates_per_vertex"] = static_cast<double>(a.model.contact_candidates()) / vertices;
    s["neighbour_list_builds"] = a.model.neighbour_list_builds();
    s["kinetic_energy_final"] = a.model.kinetic_energy();
}

// spd.compaction (section 5, Figs. 26-29).
void run_compaction(const Parameters& p, RunContext& ctx)
{
    CompactionSetup setup;
    setup.assembly.particles = static_cast<int>(p.integer("particles"));
    setup.assembly.ring.nodes = static_cast<int>(p.integer("nodes"));
    setup.assembly.ring.eta = p.real("eta");
    setup.assembly.ring.plastic_ratio = p.real("plastic_ratio");
    setup.assembly.radius_spread = p.real("polydispersity");
    setup.assembly.seed = static_cast<std::uint64_t>(p.integer("seed"));
    setup.wall_speed = p.real("wall_speed");
    setup.strain_max = p.real("strain_max");
    ctx.record_seed(setup.assembly.seed);
    auto progress = ctx.progress("spd.compaction");
    const CompactionResult r = compaction(setup, [&](double f) { progress.update(f); });
    progress.finish();
    ctx.count_steps(r.steps);

    auto& table = ctx.table("compaction.dat",
                            {{"eps", "1", "ln(H0/H)"},
                             {"loading", "1", "1 loading, 0 unloading"},
                             {"sigma_over_sigma_star", "1", "top-wall stress F/(W s) over sigma* (eq. 37)"},
                             {"sigma_bottom_over_sigma_star", "1", "bottom-wall stress over sigma*"},
                             {"e", "1", "void ratio (V - V_s)/V_s"},
                             {"dVs_over_dV", "1", "Delta V_s / Delta V"},
                             {"kinetic_energy", "J", "kinetic energy"}});
    double sigma_max = 0, dv_peak = 0, residual = 0;
    bool released = false;
    for (const CompactionState& st : r.states) {
        table.row({st.strain, st.loading ? 1.0 : 0.0, st.stress / r.sigma_star,
                   st.stress_bottom / r.sigma_star, st.void_ratio, st.volume_change_ratio,
                   st.kinetic_energy});
        sigma_max = std::max(sigma_max, st.stress);
        if (st.loading && std::isfinite(st.volume_change_ratio))
            dv_peak = std::max(dv_peak, st.volume_change_ratio);
    }
    // Residual strain: the strain at which the unloading stress first falls below 1% of its largest value.
    for (const CompactionState& st : r.states)
        if (!st.loading && !released && st.stress < 0.01 * sigma_max) {
            residual = st.strain;
            released = true;
        }
    // Compressibility index C of eq. (38): slope of e against -log10(sigma/sigma*) over the loading states
    // within one decade below the largest stress.
    std::vector<double> log_sigma, e;
    for (const CompactionState& st : r.states)
        if (st.loading && st.stress > 0.1 * sigma_max) {
            log_sigma.push_back(std::log10(st.stress / r.sigma_star));
            e.push_back(st.void_ratio);
        }
    double C = NAN;
    if (log_sigma.size() >= 3) {
        double c0, c1, cov00, cov01, cov11, ss;
        gsl_fit_linear(log_sigma.data(), 1, e.data(), 1, e.size(), &c0, &c1, &cov00, &cov01, &cov11, &ss);
        C = -c1;
    }
    const auto at_max = std::max_element(r.states.begin(), r.states.end(),
                                         [](const auto& u, const auto& w) { return u.strain < w.strain; });
    double mean_energy = 0;
    for (double W : r.energy_at_max)
        mean_energy += W / r.energy_at_max.size();
    auto& particles = ctx.table("particles_at_max.dat", {{"particle", "1", "index"},
                                                         {"x", "m", "vertex x"},
                                                         {"y", "m", "vertex y"},
                                                         {"W_over_mean", "1", "elastic energy W_i/<W>"}});
    for (std::size_t k = 0; k < r.shape_x.size(); ++k)
        for (std::size_t j = 0; j <= r.shape_x[k].size(); ++j) { // closed outline: first vertex repeated
            const std::size_t v = j % r.shape_x[k].size();
            particles.row({static_cast<double>(k), r.shape_x[k][v], r.shape_y[k][v],
                           mean_energy > 0 ? r.energy_at_max[k] / mean_energy : 0.0});
        }
    auto& s = ctx.summary();
    s["e0"] = r.e0;
    s["e_at_max"] = at_max->void_ratio;
    s["e_final"] = r.states.back().void_ratio;
    s["strain_at_max"] = at_max->strain;
    s["sigma_max_over_sigma_star"] = sigma_max / r.sigma_star;
    s["dVs_over_dV_at_max"] = at_max->volume_change_ratio;
    s["dVs_over_dV_peak"] = dv_peak;
    s["compressibility_index"] = std::isfinite(C) ? nlohmann::json(C) : nlohmann::json(nullptr);
    s["residual_strain"] = released ? nlohmann::json(residual) : nlohmann::json(nullptr);
    s["wall_balance_at_max"] = (at_max->stress - at_max->stress_bottom) / at_max->stress;
    s["H0"] = r.H0;
    s["width"] = r.width;
    s["dt"] = r.dt;
    s["dt_critical"] = r.dt_critical;
    s["deposition_steps"] = r.deposition_steps;
}

} // namespace

void register_spd_assembly_scenes(SceneRegistry& registry)
{
    registry.add(Scene{
        "spd.bench",
        "SPD speed: elastic rings colliding in a box; vertex-steps per second of the time-step loop",
        {
            ParameterSpec::integer("particles", 400, "1", "number of rings").at_least(1),
            ParameterSpec::integer("nodes", 32, "1", "vertices per ring").at_least(8),
            ParameterSpec::integer("steps", 2000, "1", "time steps (the first is not timed)").at_least(2),
            ParameterSpec::integer("seed", 1, "1", "seed of the initial velocities").non_negative(),
        },
        run_bench});
    registry.add(Scene{
        "spd.compaction",
        "SPD section 5: uniaxial compaction and decompaction of polydisperse core-shell rings (Figs. 26-29)",
        {
            ParameterSpec::integer("particles", 25, "1", "number of rings (the paper: 500)").at_least(2),
            ParameterSpec::integer("nodes", 16, "1", "vertices per ring").at_least(8),
            ParameterSpec::real("eta", 0.0, "1",
                                "core-to-shell stiffness ratio K_Omega/K_shell, eq. (24); inf: "
                                "incompressible core (exact area constraint)")
                .non_negative()
                .infinity_allowed(),
            ParameterSpec::real("plastic_ratio", INFINITY, "1", "M_b^Y/M* (eq. (32)); inf: elastic")
                .positive()
                .infinity_allowed(),
            ParameterSpec::real(
                "wall_speed", 0.01, "R omega_2",
                "top-wall speed over R omega_2 (omega_2 the ovalisation frequency of a free ring)")
                .positive(),
            ParameterSpec::real("strain_max", 0.3, "1", "turning point eps = ln(H0/H)").positive().below(1.0),
            ParameterSpec::real("polydispersity", 0.15, "1", "standard deviation of the radii Delta R/R")
                .non_negative()
                .below(0.4),
            ParameterSpec::integer("seed", 1, "1", "seed of the radii and of the deposition layout")
                .non_negative(),
        },
        run_compaction});
}

} // namespace softgrain
