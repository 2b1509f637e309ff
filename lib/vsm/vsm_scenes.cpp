// Scenes of the Voronoi strain-based method (Frenning 2022).
#include "vsm/vsm_scenes.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "vsm/l_block.hpp"
#include "vsm/patch_test.hpp"
#include "vsm/punch.hpp"
#include "vsm/swinging_cube.hpp"
#include "vsm/vtk_frames.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace softgrain {

namespace {

using namespace vsm;

InternalForce internal_force_choice(const Parameters& p)
{
    return p.choice("internal_force") == "eq43" ? InternalForce::eq43 : InternalForce::eq41;
}

// The material and arrangement parameters every VSM scene shares, with each scene's own default.
ParameterSpec young_modulus(double value)
{
    return ParameterSpec::real("E", value, "Pa", "Young's modulus").positive();
}

ParameterSpec poisson_ratio(double value)
{
    return ParameterSpec::real("nu", value, "1", "Poisson's ratio").at_least(-0.99).below(0.5);
}

ParameterSpec density(double value)
{
    return ParameterSpec::real("rho", value, "kg/m^3", "density").positive();
}

ParameterSpec jitter_seed()
{
    return ParameterSpec::seed("seed", 1, "seed of the jitter");
}

ParameterSpec time_step_check()
{
    return ParameterSpec::boolean(
        "time_step_check", true,
        "refuse a time step above the predicted stability limit C_stab L_min / c_eff "
        "(vsm/stability.hpp) before the run (exit 3); false only for stability "
        "studies");
}

ParameterSpec internal_force_parameter(const std::string& default_value)
{
    return ParameterSpec::choice(
        "internal_force", default_value, {"eq41", "eq43"},
        "internal force: eq41 = eq. (41) in its pairwise form (42) with reactions (static "
        "form), eq43 = angular-momentum-preserving eq. (43)");
}

void run_patch(const Parameters& p, RunContext& context)
{
    PatchSetup s;
    const std::string& test = p.choice("test");
    s.variant = test == "A" ? PatchVariant::A : test == "B" ? PatchVariant::B : PatchVariant::C;
    s.per_side = static_cast<int>(p.integer("per_side"));
    s.jitter = p.real("jitter");
    s.seed = static_cast<std::uint64_t>(p.integer("seed"));
    s.alpha = p.real("alpha");
    s.material = {p.real("E"), p.real("nu"), p.real("rho")};
    s.options = {internal_force_choice(p), p.real("xi"), p.real("xi")};
    s.ramp_time = p.real("ramp_time");
    s.hold_time = p.real("hold_time");
    s.cfl = p.real("cfl");
    s.time_step_check = p.boolean("time_step_check");
    s.damping = p.real("damping");
    context.record_seed(s.seed);
    // ParaView frames (time value t [s], field data load r(t) and test 1 A, 2 B, 3 C): test A has one state,
    // the exact positions at which it measures the forces; B and C every 1000 time steps of the ramp and hold
    // (--vtk-every N: every N steps) and always the final state, whose error the summary reports.
    const PatchObserver frame = [&](const PatchState& q) {
        if (!q.final && !context.vtk()->due(q.step, 1000)) return;
        context.vtk()->write(q.t,
                             vsm_frame(q.model, q.x, q.v, q.t, q.step,
                                       {{"load", q.load}, {"test", static_cast<double>(s.variant) + 1}}));
    };
    const PatchResult r = run_patch_test(s, context.vtk() ? frame : PatchObserver{});
    // Test A's error is relative to the particle force E alpha h^2: when that under- or overflows (e.g.
    // E = 4.9e-324 Pa) there is no error to measure, only 0/0.
    if (s.variant == PatchVariant::A && !(r.force_scale > 0 && std::isfinite(r.force_scale)))
        throw NumericalError("patch test A: the force scale E alpha h^2 = " + std::to_string(r.force_scale) +
                                 " N is not a positive finite number",
                             0, "E or alpha so small or large that the particle forces under- or overflow");
    context.count_steps(r.steps);
    auto& particles =
        context.table("particles.dat", {{"X1", "m", "reference position"}, {"X2", "m", ""}, {"X3", "m", ""}});
    for (Eigen::Index a = 0; a < r.X.cols(); ++a)
        particles.row({r.X(0, a), r.X(1, a), r.X(2, a)});
    auto& out = context.summary();
    out["max_error"] = r.max_error;
    out["test_id"] = static_cast<int>(s.variant) + 1; // 1 = A, 2 = B, 3 = C (numeric, for tables)
    out["max_error_unit"] = s.variant == PatchVariant::A ? "N" : "m";
    // Relative error: to the typical particle force E alpha h^2 (A) or to the largest exact displacement (B,
    // C).
    const double displacement_scale = patch_displacement_gradient(s.alpha).rowwise().sum().norm();
    out["relative_error"] = r.max_error / (s.variant == PatchVariant::A ? r.force_scale : displacement_scale);
    out["force_scale"] = r.force_scale;
    out["final_residual_force"] = s.variant == PatchVariant::A ? nullptr : nlohmann::json(r.final_residual);
    out["particles"] = r.particles;
    out["dt"] = s.variant == PatchVariant::A ? nullptr : nlohmann::json(r.dt);
}

void run_swinging_cube_scene(const Parameters& p, RunContext& context)
{
    SwingingCubeSetup s;
    s.per_side = static_cast<int>(p.integer("per_side"));
    s.jitter = p.real("jitter");
    s.seed = static_cast<std::uint64_t>(p.integer("seed"));
    s.cube.material = {p.real("E"), p.real("nu"), p.real("rho")};
    s.cube.amplitude *= p.real("amplitude_scale");
    // The displacement must be resolved in positions of order 1 m: below 1e-10 m its rounding (2e-6
    // relative) approaches the discretisation error the scene measures, and at 1e-300 the relative errors
    // were 0/0.
    if (!(s.cube.amplitude.cwiseAbs().maxCoeff() >= 1e-10))
        throw InputError("'amplitude_scale' = " + number_text(p.real("amplitude_scale")) +
                         " makes the largest displacement amplitude " +
                         number_text(s.cube.amplitude.cwiseAbs().maxCoeff()) +
                         " m; allowed: amplitudes of at least 1e-10 m (resolved in positions of order 1 m)");
    s.options = {internal_force_choice(p), p.real("xi"), p.real("xi")};
    s.end_time = p.real("end_time");
    s.cfl = p.real("cfl");
    s.time_step_check = p.boolean("time_step_check");
    context.record_seed(s.seed);
    auto& history = context.table(
        "error_history.dat",
        {{"t", "s", "time"},
         {"error_l2", "1", "normalised L2 displacement error against eq. (53)"},
         {"error_boundary_layer", "1", "the same over the particles within one spacing of a face"},
         {"error_interior", "1", "the same over the other particles"},
         {"mode_amplitude", "1", "projection c(t) of u_a on the mode shape u(X_a, 0) (exact: cos omega t)"},
         {"residual", "1", "sqrt(sum |u_a - c phi_a|^2 / sum |phi_a|^2): the part that is not the mode"}});
    // ParaView frames at every time step (--vtk-every N: every N-th), time value t [s]; field data
    // cos_omega_t, the exact mode amplitude of eq. (53).
    const double omega = s.cube.angular_frequency();
    const StepObserver frame = [&](const Model& model, const Leapfrog& integrator) {
        if (context.vtk() && context.vtk()->due(integrator.state().step))
            context.vtk()->write(
                integrator.state().t,
                vsm_frame(model, integrator, {{"cos_omega_t", std::cos(omega * integrator.state().t)}}));
    };
    const auto start = std::chrono::steady_clock::now();
    const SwingingCubeResult r = run_swinging_cube(
        s,
        [&](const SwingingCubeError& e) {
            history.row({e.t, e.l2, e.boundary_layer, e.interior, e.mode_amplitude, e.residual});
        },
        static_cast<int>(p.integer("history_samples")), context.vtk() ? frame : StepObserver{});
    const double wall = seconds_since(start);
    context.count_steps(r.steps);
    auto& particles = context.table("particles.dat", {{"X1", "m", "reference position"},
                                                      {"X2", "m", ""},
                                                      {"X3", "m", ""},
                                                      {"von_mises", "Pa", "von Mises stress at t = 0"}});
    for (Eigen::Index a = 0; a < r.X.cols(); ++a)
        particles.row({r.X(0, a), r.X(1, a), r.X(2, a), r.initial_von_mises[static_cast<std::size_t>(a)]});
    auto& out = context.summary();
    out["displacement_error_l2"] = r.displacement_error_l2;
    out["initial_von_mises_error_l2"] = r.initial_von_mises_error_l2; // against eq. (53) at X_a (Fig. 4)
    out["displacement_error_l2_boundary_layer"] = r.error.boundary_layer;
    out["displacement_error_l2_interior"] = r.error.interior;
    // The split |e|^2 = |c - cos(omega t)|^2 |phi|^2 + |r|^2 (r orthogonal to phi), normalised like the
    // total: the error of the swinging mode itself (phase and amplitude) and the rest (other modes).
    const double cos_wt = std::cos(s.cube.angular_frequency() * r.error.t);
    out["displacement_error_mode_part"] = std::abs(r.error.mode_amplitude - cos_wt) / std::abs(cos_wt);
    out["displacement_error_other_part"] = r.error.residual / std::abs(cos_wt);
    out["spacing"] = r.spacing;
    out["particles"] = r.particles;
    out["dt"] = r.dt;
    out["dt_over_limit"] = r.dt / r.dt_limit; // predicted limit C_stab L_min / c_eff (vsm/stability.hpp)
    out["omega"] = s.cube.angular_frequency();
    out["period"] = 2 * std::numbers::pi / s.cube.angular_frequency();
    out["run_wall_time_s"] = wall; // reference cells + model setup + time stepping
    out["cost_per_step_per_particle_s"] = wall / (static_cast<double>(r.steps) * r.particles);
}

void run_l_block_scene(const Parameters& p, RunContext& context)
{
    LBlockSetup s;
    s.spacing = p.real("spacing");
    s.material = {p.real("E"), p.real("nu"), p.real("rho")};
    s.options = {internal_force_choice(p), p.real("xi"), p.real("xi")};
    s.load = Vec3(p.real("load_1"), p.real("load_2"), p.real("load_3"));
    s.end_time = p.real("end_time");
    s.cfl = p.real("cfl");
    s.time_step_check = p.boolean("time_step_check");
    if (s.end_time <= 5.0)
        throw InputError("end_time = " + std::to_string(s.end_time) + " must exceed 5 s (the load)");
    auto& momentum =
        context.table("momentum.dat", {{"t", "s", "time"},
                                       {"p1", "kg m/s", "linear momentum sum m v, component 1"},
                                       {"p2", "kg m/s", "component 2"},
                                       {"p3", "kg m/s", "component 3"},
                                       {"l1", "kg m^2/s", "angular momentum about the origin, 1"},
                                       {"l2", "kg m^2/s", "component 2"},
                                       {"l3", "kg m^2/s", "component 3"}});
    auto& shapes = context.table("shapes.dat", {{"t", "s", "time of the snapshot"},
                                                {"x1", "m", "current position"},
                                                {"x2", "m", ""},
                                                {"x3", "m", ""}});
    const std::vector<double> snapshot_times{0, 5, 10, 20, 35, 55};
    std::size_t next_snapshot = 0;
    auto progress = context.progress("vsm.lblock");
    const auto observe = [&](const LBlockSample& q, const Points<3>& x) {
        momentum.row(
            {q.t, q.linear.x(), q.linear.y(), q.linear.z(), q.angular.x(), q.angular.y(), q.angular.z()});
        progress.update(q.t / s.end_time);
        if (next_snapshot < snapshot_times.size() && q.t >= snapshot_times[next_snapshot] - 1e-9) {
            for (Eigen::Index a = 0; a < x.cols(); ++a)
                shapes.row({q.t, x(0, a), x(1, a), x(2, a)});
            ++next_snapshot;
        }
    };
    // ParaView frames every 50 time steps (--vtk-every N: every N steps), time value t [s]; field data
    // traction_pulse p(t) of the load.
    const StepObserver frame = [&](const Model& model, const Leapfrog& integrator) {
        if (context.vtk() && context.vtk()->due(integrator.state().step, 50))
            context.vtk()->write(
                integrator.state().t,
                vsm_frame(model, integrator, {{"traction_pulse", l_block_pulse(integrator.state().t)}}));
    };
    const auto start = std::chrono::steady_clock::now();
    const LBlockResult r = run_l_block(s, 10, observe, context.vtk() ? frame : StepObserver{});
    const double wall = seconds_since(start);
    progress.finish();
    context.count_steps(r.steps);
    auto& out = context.summary();
    out["internal_force_id"] = s.options.internal == InternalForce::eq43 ? 43 : 41;
    out["linear_momentum_drift"] = r.linear_momentum_drift;
    out["linear_momentum_drift_relative"] = r.linear_momentum_drift / r.impulse_scale;
    out["angular_momentum_drift_after_load"] = r.angular_momentum_drift_after_load;
    out["angular_momentum_after_load"] = r.angular_momentum_after_load.norm();
    // Not applicable when the load leaves no angular momentum (a zero traction): the ratio would be 0/0.
    const double angular_momentum = r.angular_momentum_after_load.norm();
    out["angular_momentum_drift_after_load_relative"] =
        angular_momentum > 0 ? nlohmann::json(r.angular_momentum_drift_after_load / angular_momentum)
                             : nlohmann::json(nullptr);
    out["impulse_scale"] = r.impulse_scale;
    out["particles"] = r.particles;
    out["dt"] = r.dt;
    out["cost_per_step_per_particle_s"] = wall / (static_cast<double>(r.steps) * r.particles);
}

void run_punch_scene(const Parameters& p, RunContext& context)
{
    PunchSetup s;
    const int n = static_cast<int>(p.integer("per_side"));
    if ((2 * n - 1) % 3 != 0)
        throw InputError(
            "per_side = " + std::to_string(n) +
            " gives 2 per_side - 1 particles across the width, which must be divisible by 3 (the "
            "punch covers the middle third): use 2, 5, 8, 11, 14, ...");
    s.counts = {2 * n - 1, n, static_cast<int>(p.integer("layers"))};
    s.jitter = p.choice("arrangement") == "irregular" ? p.real("jitter") : 0.0;
    s.seed = static_cast<std::uint64_t>(p.integer("seed"));
    s.material = {p.real("E"), p.real("nu"), p.real("rho")};
    s.options = {internal_force_choice(p), p.real("xi"), p.real("xi"), p.real("c1"), p.real("c2")};
    s.punch_velocity = p.real("punch_velocity");
    s.snapshot_strains = {0.5 * p.real("final_strain"), p.real("final_strain")};
    s.cfl = p.real("cfl");
    s.time_step_check = p.boolean("time_step_check");
    context.record_seed(s.seed);
    auto& snapshots = context.table("snapshots.dat", {{"strain", "1", "punch displacement / height"},
                                                      {"x1", "m", "current position"},
                                                      {"x2", "m", ""},
                                                      {"x3", "m", ""},
                                                      {"pressure", "Pa", "Cauchy pressure -tr(sigma)/3"}});
    std::vector<PunchSnapshot> taken;
    // ParaView frames every 100 time steps (--vtk-every N: every N steps), time value t [s]: the particles
    // (pressure as in Fig. 10) and the walls, the punch moving down; field data punch_displacement v t [m]
    // and strain v t / height.
    const StepObserver frame = [&](const Model& model, const Leapfrog& integrator) {
        if (!context.vtk() || !context.vtk()->due(integrator.state().step, 100)) return;
        const double displacement = s.punch_velocity * integrator.state().t;
        context.vtk()->write(integrator.state().t,
                             vsm_frame(model, integrator,
                                       {{"punch_displacement", displacement},
                                        {"strain", displacement / model.domain().high.y()}}));
    };
    const auto start = std::chrono::steady_clock::now();
    const PunchResult r = run_punch(
        s, [&](const PunchSnapshot& q) { taken.push_back(q); }, context.vtk() ? frame : StepObserver{});
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    context.count_steps(r.steps);
    auto& out = context.summary();
    const char* tags[] = {"half", "final"};
    for (std::size_t k = 0; k < taken.size(); ++k) {
        const PunchSnapshot& q = taken[k];
        for (Eigen::Index a = 0; a < q.x.cols(); ++a) {
            snapshots.row(
                {q.strain, q.x(0, a), q.x(1, a), q.x(2, a), q.pressure[static_cast<std::size_t>(a)]});
        }
        const std::string tag = tags[k];
        out["punch_force_" + tag] = q.punch_force;
        out["nonaffine_ratio_" + tag] = q.nonaffine_ratio;
        out["pressure_roughness_" + tag] = q.pressure_roughness;
        out["pressure_max_" + tag] = *std::max_element(q.pressure.begin(), q.pressure.end());
    }
    out["jitter"] = s.jitter; // effective: 0 for the regular arrangement
    out["particles"] = r.particles;
    out["dt"] = r.dt;
    out["dt_over_limit"] = r.dt / r.dt_limit; // predicted limit C_stab L_min / c_eff (vsm/stability.hpp)
    out["cost_per_step_per_particle_s"] = wall / (static_cast<double>(r.steps) * r.particles);
}

// The memory of a VSM body of `particles` particles: 13 kB per particle, measured as the growth of peak RSS
// between vsm.patch runs of 6^3 and 14^3 particles (Voronoi cells, neighbour lists, the matrices K'_a).
MemoryEstimate vsm_particle_memory(double particles, const std::string& what)
{
    return per_item_memory(particles, 13e3, what);
}

double cube(double x)
{
    return x * x * x;
}

} // namespace

void register_vsm_scenes(SceneRegistry& registry)
{
    registry.add(Scene{
        "vsm.patch",
        "VSM patch tests A, B, C (Frenning Table 1): irregular particles in the unit cube, linear field eq. "
        "(52)",
        {
            ParameterSpec::choice(
                "test", "A", {"A", "B", "C"},
                "A: all particles prescribed, force error; B: displacement on all faces; C: "
                "displacement on X3 = 0, tractions elsewhere"),
            ParameterSpec::integer("per_side", 3, "1", "particles per side of the cube").at_least(2),
            ParameterSpec::real("jitter", 0.25, "1",
                                "uniform jitter of each coordinate, fraction of the spacing")
                .non_negative()
                .below(0.5),
            jitter_seed(),
            ParameterSpec::real("alpha", 1e-4, "1", "amplitude alpha of the linear field, eq. (52)")
                .positive(),
            young_modulus(1.0e6),
            poisson_ratio(0.3),
            density(1.0e3),
            ParameterSpec::real("xi", 1.0, "1", "contact factors xi_n = xi_t of eq. (50)").non_negative(),
            internal_force_parameter("eq41"),
            ParameterSpec::real("ramp_time", 50.0, "s", "B, C: linear ramp of the loads (paper: 50 s)")
                .positive(),
            ParameterSpec::real("hold_time", 10.0, "s",
                                "B, C: time at full load before the error is measured")
                .positive(),
            ParameterSpec::real("cfl", 0.3, "1", "time step dt = cfl L_min / c_p").positive().at_most(1.0),
            time_step_check(),
            ParameterSpec::real("damping", 40.0, "1/s", "B, C: mass-proportional damping coefficient")
                .non_negative(),
        },
        run_patch,
    }
                     .needing([](const Parameters& p) {
                         return vsm_particle_memory(cube(double(p.integer("per_side"))),
                                                    "particles (per_side^3)");
                     })
                     .with_vtk());
    registry.add(Scene{
        "vsm.swinging_cube",
        "VSM swinging cube (Frenning Fig. 5): displacement error against the linear solution eq. (53) at t = "
        "5 ms",
        {
            ParameterSpec::integer("per_side", 8, "1", "particles per side of the unit cube").at_least(3),
            ParameterSpec::real("jitter", 0.1, "1",
                                "uniform jitter of each coordinate, fraction of the spacing")
                .non_negative()
                .below(0.5),
            jitter_seed(),
            young_modulus(17.0e6),
            poisson_ratio(0.45),
            density(1.1e3),
            ParameterSpec::real("amplitude_scale", 1.0, "1",
                                "factor on (U1, U2, U3) = (5e-4, 5e-4, -1e-3) m (linear-regime check)")
                .positive(),
            ParameterSpec::real("xi", 1.0, "1", "contact factors xi_n = xi_t of eq. (50)").non_negative(),
            internal_force_parameter("eq43"),
            ParameterSpec::real("end_time", 5e-3, "s", "time at which the error is measured").positive(),
            ParameterSpec::integer("history_samples", 20, "1",
                                   "samples of the error history (error_history.dat), besides t = 0")
                .non_negative(),
            ParameterSpec::real("cfl", 0.3, "1",
                                "time step dt = cfl L_min / c_p (rounded down to hit end_time)")
                .positive()
                .at_most(2.0),
            time_step_check(),
        },
        run_swinging_cube_scene,
    }
                     .needing([](const Parameters& p) {
                         return vsm_particle_memory(cube(double(p.integer("per_side"))),
                                                    "particles (per_side^3)");
                     })
                     .with_vtk());
    registry.add(Scene{
        "vsm.lblock",
        "VSM L-shaped block (Frenning Figs. 6-8): free block, traction pulse, momentum conservation",
        {
            ParameterSpec::real("spacing", 0.5, "m", "regular lattice spacing (must divide 6, 10 and 3 m)")
                .positive(),
            internal_force_parameter("eq43"),
            young_modulus(50.0e3),
            poisson_ratio(0.3),
            density(1.0e3),
            ParameterSpec::real("xi", 1.0, "1", "contact factors xi_n = xi_t of eq. (50)").non_negative(),
            ParameterSpec::real("load_1", 150.0, "Pa", "component 1 of the traction vector times p(t)"),
            ParameterSpec::real("load_2", 300.0, "Pa", "component 2"),
            ParameterSpec::real("load_3", 900.0, "Pa", "component 3 (printed 900; 450 in related papers)"),
            ParameterSpec::real("end_time", 55.0, "s", "duration (load acts for 5 s)").positive(),
            ParameterSpec::real("cfl", 0.3, "1", "time step dt = cfl L_min / c_p").positive().at_most(2.0),
            time_step_check(),
        },
        run_l_block_scene,
    }
                     .needing([](const Parameters& p) {
                         // The L of arms 6 x 3 x 3 m and 3 x 7 x 3 m: 117 m^3.
                         return vsm_particle_memory(117.0 / cube(p.real("spacing")),
                                                    "particles (117 m^3 / spacing^3)");
                     })
                     .with_vtk());
    registry.add(Scene{
        "vsm.punch",
        "VSM punch test (Frenning Figs. 9-10): rigid punch on the middle third, stabilisation xi, pressure "
        "field",
        {
            ParameterSpec::integer(
                "per_side", 11, "1",
                "particles over the height; (2 per_side - 1) over the width (21 x 11 in the paper)")
                .at_least(2),
            ParameterSpec::integer("layers", 3, "1", "particles over the thickness").at_least(1),
            ParameterSpec::choice("arrangement", "regular", {"regular", "irregular"},
                                  "regular cell-centred lattice, or jittered by `jitter` of the spacing"),
            ParameterSpec::real("jitter", 0.2, "1", "irregular arrangement: jitter fraction")
                .non_negative()
                .below(0.5),
            jitter_seed(),
            young_modulus(1.0e6),
            poisson_ratio(0.45),
            density(1.0e3),
            ParameterSpec::real("xi", 1.0, "1", "contact (stabilisation) factors xi_n = xi_t of eq. (50)")
                .non_negative(),
            ParameterSpec::real("c1", 0.1, "1", "artificial viscosity, linear term of eq. (51)")
                .non_negative(),
            ParameterSpec::real("c2", 0.1, "1", "artificial viscosity, quadratic term of eq. (51)")
                .non_negative(),
            internal_force_parameter("eq43"),
            ParameterSpec::real("punch_velocity", 0.1, "m/s", "downward punch velocity").positive(),
            ParameterSpec::real("final_strain", 0.3, "1",
                                "punch displacement / height at the end; snapshots at half and at the end")
                .positive()
                .below(1.0),
            ParameterSpec::real("cfl", 0.3, "1", "time step dt = cfl L_min / c_p").positive().at_most(2.0),
            time_step_check(),
        },
        run_punch_scene,
    }
                     .needing([](const Parameters& p) {
                         const double per_side = double(p.integer("per_side"));
                         return vsm_particle_memory(per_side * (2 * per_side - 1) *
                                                        double(p.integer("layers")),
                                                    "particles (per_side x (2 per_side - 1) x layers)");
                     })
                     .with_vtk());
}

} // namespace softgrain
