// spd.compaction (Trivino et al., section 5, Figs. 26-29): uniaxial compaction and unloading of
// polydisperse core-shell rings deposited under gravity.
#include "spd/compaction.hpp"
#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "spd/assembly.hpp"
#include "spd/scenes/parameters.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/vtk_frames.hpp"

#include <cmath>
#include <optional>

namespace softgrain::spd {

namespace {

OptionBinding<CompactionSetup> compaction_binding()
{
    const auto ring = [](auto... field) {
        return path(&CompactionSetup::assembly, &AssemblySetup::ring, field...);
    };
    OptionBinding<CompactionSetup> binding(compaction_scene_defaults());
    binding
        .integer(path(&CompactionSetup::assembly, &AssemblySetup::particles), "particles", "1",
                 "number of rings (the paper: 500)")
        .at_least(2);
    binding.integer(ring(&RingSetup::nodes), "nodes", "1", "vertices per ring").at_least(8);
    binding
        .real(ring(&RingSetup::material, &ShellMaterial::h), "h", "m",
              "shell thickness (2r = h; mean ring radius R = 1 m)")
        .positive();
    binding
        .real(path(&CompactionSetup::assembly, &AssemblySetup::radius_spread), "radius_spread", "1",
              "Delta R/R, standard deviation of the radii")
        .non_negative()
        .below(0.5);
    binding
        .real(ring(&RingSetup::eta), "eta", "1",
              "core-to-shell stiffness ratio, eq. (24); inf: incompressible core")
        .non_negative()
        .infinity_allowed();
    binding
        .real(ring(&RingSetup::plastic_ratio), "plastic_ratio", "1",
              "M_b^Y/M*, eq. (32); inf: elastic shells")
        .positive()
        .infinity_allowed();
    binding
        .real(&CompactionSetup::wall_speed, "wall_speed", "R omega_2",
              "top-wall speed over R omega_2 (omega_2: ovalisation frequency of a free ring)")
        .positive();
    binding.real(&CompactionSetup::strain_max, "strain_max", "1", "largest vertical strain ln(H0/H)")
        .positive()
        .below(1.0);
    binding
        .real(&CompactionSetup::stress_max, "stress_max", "sigma*",
              "loading also ends when sigma reaches this (incompressible rings jam before eps = ln(V0/V_s))")
        .positive()
        .infinity_allowed();
    binding.real(&CompactionSetup::gravity, "gravity", "EI/R^2", "particle weight during the deposition")
        .positive();
    binding
        .real(&CompactionSetup::rest_tolerance, "rest_tolerance", "particle weight",
              "deposition at rest when the largest unbalanced vertex force is below this")
        .positive();
    binding
        .real(ring(&RingSetup::dt_factor), "dt_factor", "1",
              "time step over dt_c = sqrt(m/k_max); stable for a vertex-vertex contact below 0.236 "
              "(decisions spd-compaction-time-step, spd-vertex-pair-stability)")
        .positive();
    binding.seed(path(&CompactionSetup::assembly, &AssemblySetup::seed), "seed",
                 "seed of the radii and of the deposition");
    binding.check([](const CompactionSetup& setup) {
        const RingSetup& ring_setup = setup.assembly.ring;
        if (ring_setup.material.h >= 0.5 * ring_setup.radius)
            throw InputError("h = " + std::to_string(ring_setup.material.h) +
                             ": the shell must be thin against the ring; allowed: h < 0.5 R = 0.5 m");
    });
    return binding;
}

// compaction.dat: every recorded state of the loading and the unloading.
void write_compaction_table(const CompactionSetup& setup, const CompactionResult& result, RunContext& context)
{
    const double R = setup.assembly.ring.radius;
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
    for (const CompactionState& state : result.states)
        table.row({state.strain, state.loading ? 1.0 : 0.0, state.height / R,
                   top_stress_over_sigma_star(setup, result, state),
                   bottom_stress_over_sigma_star(setup, result, state), void_ratio(result, state),
                   solid_volume_share(result, state), state.kinetic_energy / (result.deposit.weight * R)});
}

// snapshot.dat: the particles at the stored snapshots of the loading, each with W_i/<W> (Figs. 26, 29).
void write_snapshots(const CompactionSetup& setup, const CompactionResult& result, RunContext& context)
{
    const double R = setup.assembly.ring.radius;
    auto& snapshot = context.table(
        "snapshot.dat",
        {{"snapshot", "1", "0: first contact of the top wall (H0), ..., last: end of loading (Figs. 26, 29)"},
         {"eps", "1", "ln(H0/H) of the snapshot"},
         {"H_over_R", "1", "top-wall height over the mean radius"},
         {"particle", "1", "particle index"},
         {"x_over_R", "1", "vertex position over the mean radius (closed polygon)"},
         {"y_over_R", "1", "vertex position"},
         {"W_over_mean", "1", "elastic energy W_i of the particle over <W> of the snapshot (Fig. 29)"}});
    for (std::size_t n = 0; n < result.snapshots.size(); ++n) {
        const CompactionSnapshot& snap = result.snapshots[n];
        double energy_mean = 0;
        for (double energy : snap.energy)
            energy_mean += energy / static_cast<double>(snap.energy.size());
        for (std::size_t i = 0; i < snap.particles.size(); ++i)
            for (std::size_t k = 0; k <= snap.particles[i].size(); ++k) {
                const Vec2& x = snap.particles[i][k % snap.particles[i].size()];
                // NaN only if no ring is deformed at all (<W> = 0).
                snapshot.row({double(n), snap.strain, snap.height / R, double(i), x.x() / R, x.y() / R,
                              energy_mean > 0 ? snap.energy[i] / energy_mean : NAN});
            }
    }
}

void write_summary(const CompactionSetup& setup, const CompactionResult& result,
                   const CompactionMeasures& measures, RunContext& context)
{
    const double R = setup.assembly.ring.radius;
    const std::optional<Line>& compressibility = measures.compressibility;
    auto& summary = context.summary();
    summary["e0"] = void_ratio(result, result.states.front());
    summary["e_at_strain_max"] = void_ratio(result, measures.end_of_loading);
    summary["e_after_unloading"] = void_ratio(result, result.states.back());
    summary["strain_at_max"] = measures.end_of_loading.strain;
    summary["sigma_over_sigmastar_max"] = measures.stress_max;
    summary["compressibility_index"] =
        compressibility ? nlohmann::json(-compressibility->slope) : nlohmann::json(nullptr);
    summary["compressibility_fit_e0"] =
        compressibility ? nlohmann::json(compressibility->intercept) : nlohmann::json(nullptr);
    summary["compressibility_fit_points"] = measures.compressibility_points;
    summary["dVs_over_dV_at_strain_max"] =
        finite_or_null(solid_volume_share(result, measures.end_of_loading));
    summary["dVs_over_dV_peak"] = measures.volume_share_peak;
    summary["residual_strain"] = finite_or_null(measures.residual_strain);
    summary["wall_force_mismatch_max"] = measures.wall_force_mismatch;
    const Deposit& deposit = result.deposit;
    summary["deposit_bottom_force_over_weight"] =
        deposit.bottom_force / (deposit.weight * setup.assembly.particles);
    summary["deposit_residual_over_particle_weight"] = deposit.residual_force / deposit.weight;
    summary["deposit_steps"] = deposit.steps;
    summary["disk_fire_iterations"] = deposit.disks.iterations;
    summary["H0_over_R"] = result.height0 / R;
    summary["W_over_R"] = result.width / R;
    summary["vertices"] = particle_vertices(deposit.assembly);
    summary["sigma_star"] = ring_scales(setup.assembly.ring).characteristic.sigma_star;
    summary["wall_speed_m_per_s"] = result.wall_speed;
    summary["dt"] = result.dt;
    summary["compaction_steps"] = result.steps - deposit.steps;
}

// spd.compaction (section 5, Figs. 26-29): deposition under gravity, uniaxial loading to eps = strain_max
// at constant top-wall speed, unloading back to H0 (lib/spd/compaction.hpp).
void run_compaction(const CompactionSetup& setup, RunContext& context)
{
    context.record_seed(setup.assembly.seed);
    auto progress = context.progress("spd.compaction");
    // ParaView frames at the recorded states (`records` per half cycle), the time since the top wall
    // started to move as the time value.
    const auto frame = [&](const Assembly& assembly, const CompactionState& state) {
        if (context.vtk() && context.vtk()->next())
            context.vtk()->write(state.time,
                                 shell_frame(assembly.model, assembly.particles,
                                             {assembly.bottom, assembly.top, assembly.left, assembly.right},
                                             {{"strain", state.strain},
                                              {"height", state.height},
                                              {"loading", state.loading ? 1.0 : 0.0}}));
    };
    const CompactionResult result = compaction(
        setup, frame, [&](double fraction) { progress.update(fraction); }, context.checkpoints());
    progress.finish();
    context.count_steps(result.steps); // the model counts the deposit steps too

    write_compaction_table(setup, result, context);
    write_snapshots(setup, result, context);
    write_summary(setup, result, measure_compaction(setup, result), context);
}

} // namespace

Scene compaction_scene()
{
    Scene compaction = bound_scene(
        "spd.compaction",
        "SPD section 5: uniaxial compaction and unloading of polydisperse frictionless core-shell "
        "rings deposited under gravity; sigma/sigma*, void ratio, Delta V_s/Delta V, W_i/<W> (Figs. 26-29)",
        compaction_binding(), run_compaction);
    compaction.checkpoints = true;
    return std::move(compaction)
        .needing(compaction_binding().estimate(
            [](const CompactionSetup& setup) { return rings_memory(setup.assembly); }))
        .with_vtk();
}

} // namespace softgrain::spd
