// Scenes of the SPD method (Trivino et al., sections 3-4).
#include "spd/spd_scenes.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/output.hpp"
#include "spd/beam.hpp"
#include "spd/elastica.hpp"
#include "spd/ring.hpp"
#include "spd/shell_model.hpp"
#include "spd/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace softgrain {

namespace {
using namespace spd;

ShellMaterial material_of(const Parameters& p)
{
    return {p.real("E"), p.real("nu"), p.real("h"), p.real("s"), INFINITY};
}

std::vector<ParameterSpec> material_parameters(double h)
{
    return {
        ParameterSpec::real("E", 1e6, "Pa", "Young modulus of the shell material, eqs. (10)-(11)").positive(),
        ParameterSpec::real("nu", 0.3, "1", "Poisson ratio, eqs. (10)-(11)").non_negative().below(0.5),
        ParameterSpec::real("h", h, "m", "shell thickness, eqs. (10)-(11)").positive(),
        ParameterSpec::real("s", 0.1, "m", "out-of-plane length of the particle").positive(),
    };
}

void run_beam(const Parameters& p, RunContext& context)
{
    BeamSetup b;
    b.support = p.choice("support") == "cantilever" ? BeamSupport::cantilever : BeamSupport::simple;
    b.nodes = static_cast<int>(p.integer("nodes"));
    b.material = material_of(p);
    b.length = p.real("length");
    b.force = p.real("force");
    const double theory = beam_deflection_max_theory(b);
    if (theory > 0.01 * b.length)
        throw InputError("force = " + std::to_string(b.force) +
                         ": the point-load theory is linear; allowed: a force "
                         "giving delta_max < 0.01 length (here " +
                         std::to_string(theory / b.length) + " length)");
    // ParaView frames of the damped relaxation, in which the beam settles from straight into its deflected
    // shape: the load applied (step 0), every 1000th force check (16 000 steps; --vtk-every N: every N-th
    // check, 16 N steps) and always the relaxed state, the one profile.dat lists. Time value: the step.
    const BeamObserver frame = [&](const ShellModel& model, long step, bool relaxed) {
        vtk::Series& series = *context.vtk();
        if (!relaxed && !series.next(1000)) return;
        vtk::PolyData beam = shell_walls(model, {0});
        beam.field("force", b.force);
        beam.field("step", static_cast<double>(step));
        beam.field("relaxed", relaxed ? 1.0 : 0.0);
        series.write(static_cast<double>(step), {{"beam", std::move(beam)}});
    };
    const BeamResult r = simulate_beam(b, p.real("dt_factor"), beam_force_tolerance_relative,
                                       context.vtk() ? frame : BeamObserver{});
    context.count_steps(r.steps);
    auto& profile =
        context.table("profile.dat", {{"x_over_L", "1", "node position x/L"},
                                      {"delta", "m", "downward deflection"},
                                      {"delta_over_max", "1", "delta/delta_max"},
                                      {"theory", "1", "point-load shape: eq. (14) or 3 xi - 4 xi^3"},
                                      {"eq16_printed", "1", "eq. (16) as printed (uniform-load shape)"}});
    for (std::size_t k = 0; k < r.x.size(); ++k) {
        const double xi = r.x[k] / b.length;
        profile.row(
            {xi, r.deflection[k], r.deflection[k] / r.deflection_max,
             b.support == BeamSupport::cantilever ? cantilever_shape(xi) : simple_point_load_shape(xi),
             simple_uniform_load_shape_eq16(xi)});
    }
    auto& s = context.summary();
    s["deflection_max"] = r.deflection_max;
    s["deflection_max_theory"] = theory;
    s["ratio"] = r.deflection_max / theory;
    s["ratio_discrete_theory"] = beam_discrete_ratio(b.support, b.nodes);
    s["inverse_nodes"] = 1.0 / b.nodes;
    s["support_index"] = b.support == BeamSupport::cantilever ? 0 : 1;
    s["dt"] = r.dt;
    s["dt_critical"] = r.critical_time_step;
}

RingSetup ring_setup(const Parameters& p)
{
    RingSetup r;
    r.nodes = static_cast<int>(p.integer("nodes"));
    r.radius = p.real("R");
    r.material = material_of(p);
    r.eta = p.real("eta"); // inf: incompressible core, exact area constraint (decision spd-eta-infinity)
    r.dt_factor = p.real("dt_factor");
    return r;
}

void run_ring_pressure(const Parameters& p, RunContext& context)
{
    RingSetup setup = ring_setup(p);
    if (std::isinf(setup.eta))
        throw InputError("eta = inf: an incompressible core has no volume change under pressure, so K_e is "
                         "infinite; allowed: a finite eta >= 0");
    const double pressure = p.real("pressure");
    const RingScales sc = ring_scales(setup);
    RingSetup shell_only = setup;
    shell_only.eta = 0;
    // ParaView frames, one per pressure state: the relaxed ring without its core (eta = 0, state 0; K_shell)
    // and with it (state 1; K_e). Time value: the state index; field data pressure [Pa] and eta.
    const auto frame = [&](double eta, double state) {
        return [&context, eta, state, pressure](const ShellModel& model, int ring) {
            if (!context.vtk()->next()) return;
            vtk::PolyData particles = shell_particles(model, {ring});
            particles.field("state", state);
            particles.field("pressure", pressure);
            particles.field("eta", eta);
            context.vtk()->write(state, {{"particles", std::move(particles)}});
        };
    };
    using Relaxed = std::function<void(const ShellModel&, int)>;
    const RingPressureResult shell =
        ring_under_pressure(shell_only, pressure, context.vtk() ? frame(0.0, 0) : Relaxed{});
    const RingPressureResult total =
        ring_under_pressure(setup, pressure, context.vtk() ? frame(setup.eta, 1) : Relaxed{});
    context.count_steps(shell.steps + total.steps);
    auto& s = context.summary();
    s["K_shell"] = shell.K_measured;
    s["K_shell_theory"] = sc.K_shell;
    s["K_shell_printed_approximation"] = 2 * M_PI / (setup.nodes * setup.material.s) * sc.laws.k_s;
    s["K_effective"] = total.K_measured;
    s["K_effective_theory"] = effective_bulk_modulus(setup.eta, sc.K_shell);
    s["volume_strain"] = total.volume_strain;
}

// The largest change of the least-squares slope over the abscissae x when each ordinate moves by at most
// delta: delta sum|x - mean| / sum (x - mean)^2, reached with every error of the sign of x - mean.
double slope_error_bound(const std::vector<double>& x, double delta)
{
    if (x.size() < 2) return NAN;
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
    double spread = 0, variance = 0;
    for (const double xi : x) {
        spread += std::abs(xi - mean);
        variance += (xi - mean) * (xi - mean);
    }
    return delta * spread / variance;
}

// The loading state whose strain is nearest eps.
const CompressionState& loading_state_nearest(const std::vector<CompressionState>& states, double eps)
{
    const CompressionState* best = nullptr;
    for (const CompressionState& st : states)
        if (st.loading && (!best || std::abs(st.strain - eps) < std::abs(best->strain - eps))) best = &st;
    return *best;
}

// How the top-wall contact carries the force (Figs. 16, 18, 24): the pressure at the vertex nearest the
// middle (0 if none lies within l0/2 of it), and the shares of the wall force on that vertex, on the
// outermost vertex at each edge, and on the edge zones (the outermost two at each edge: the discrete
// lift-off spreads an edge line load of the elastica over the edge vertex and its neighbour).
struct ProfileShape
{
    double centre_pressure = 0, centre_share = NAN, edge_share = NAN, edge_zone_share = NAN;
};

ProfileShape profile_shape(const CompressionState& st, double l0)
{
    ProfileShape shape;
    const std::size_t n = st.profile_x.size();
    if (n == 0) return shape;
    std::vector<std::size_t> by_x(n);
    std::iota(by_x.begin(), by_x.end(), 0);
    std::sort(by_x.begin(), by_x.end(),
              [&](std::size_t a, std::size_t b) { return st.profile_x[a] < st.profile_x[b]; });
    const auto p = [&](std::size_t rank) { return st.profile_pressure[by_x[rank]]; };
    double total = 0, centre_distance = INFINITY, edge = 0, edge_zone = 0;
    for (std::size_t k = 0; k < n; ++k) {
        total += p(k);
        const std::size_t from_edge = std::min(k, n - 1 - k);
        edge += from_edge == 0 ? p(k) : 0.0;
        edge_zone += from_edge <= 1 ? p(k) : 0.0;
        if (std::abs(st.profile_x[by_x[k]]) < centre_distance)
            centre_distance = std::abs(st.profile_x[by_x[k]]), shape.centre_pressure = p(k);
    }
    if (centre_distance >= 0.5 * l0) shape.centre_pressure = 0;
    if (total > 0)
        shape.centre_share = shape.centre_pressure / total, shape.edge_share = edge / total,
        shape.edge_zone_share = edge_zone / total;
    return shape;
}

void run_ring_compression(const Parameters& p, RunContext& context)
{
    RingSetup setup = ring_setup(p);
    setup.plastic_ratio = p.real("plastic_ratio");
    const double strain_max = p.real("strain_max");
    const bool unload = p.boolean("unload");
    const bool plastic = std::isfinite(setup.plastic_ratio);
    const RingScales sc = ring_scales(setup);
    auto progress = context.progress("spd.ring_compression");
    // ParaView frames: one per recorded load step, the step's index as the time value (the strain goes back
    // down on unloading) and the strain as field data.
    std::int64_t load_step = 0;
    const auto frame = [&](const RingBetweenWalls& w, const CompressionState& st) {
        if (context.vtk() && context.vtk()->due(load_step))
            context.vtk()->write(static_cast<double>(load_step),
                                 shell_frame(w.model, {w.ring}, {w.bottom_wall, w.top_wall},
                                             {{"load_step", static_cast<double>(load_step)},
                                              {"strain", st.strain},
                                              {"loading", st.loading ? 1.0 : 0.0}}));
        ++load_step;
    };
    const CompressionResult r = ring_compression(
        setup, strain_max, p.real("strain_step"), unload, p.real("relax_tolerance"),
        [&](double f) { progress.update(f); }, frame);
    progress.finish();
    context.count_steps(r.steps);
    const bool elastica = setup.eta == 0 && !plastic;
    const double F_star = sc.characteristic.F_star, l = sc.l0;
    auto& steps = context.table(
        "compression.dat",
        {{"eps", "1", "1 - b/b0"},
         {"loading", "1", "1 loading, 0 unloading"},
         {"a_over_b0", "1", "width a/b0"},
         {"Lc_over_b0", "1", "contact length L_c/b0 = N' l0/b0"},
         {"Lc_over_l", "1", "N' = L_c/l0"},
         {"V_over_V0", "1", "area ratio"},
         {"F_over_Fstar", "1", "wall force F/F*, F* = k_b/R eq. (30)"},
         {"F_over_F2star", "1", "F/F**, F** = M^Y/l eq. (33) (NaN if elastic)"},
         {"Ws_over_Wb", "1", "stretch over bending energy"},
         {"p", "Pa", "core pressure, eq. (4)"},
         {"p_term", "1", "1 + p s l/F*, eq. (35)"},
         {"ellipse_a_over_b0", "1", "eq. (26)"},
         {"elastica_a_over_b0", "1", "elastica reference (NaN unless eta = 0, elastic)"},
         {"elastica_Lc_over_b0", "1", "elastica flat length 2c/b0"},
         {"elastica_V_over_V0", "1", "elastica area ratio"},
         {"elastica_F_over_Fstar", "1", "elastica force F/F* = (F R^2/EI)(EI/(k_b R)), EI = k_b l0"}});
    std::vector<double> eps_late, lc_late, lc_late_elastica, lc_over_l, f_ratio;
    double volume_deviation = 0, el_volume_deviation = 0, err_a = 0, err_V = 0, err_F = 0, err_Lc = 0;
    for (const CompressionState& st : r.states) {
        ElasticaState el{};
        if (elastica) el = elastica_ring_between_plates(st.strain);
        const double nan = NAN;
        const double F2 = plastic ? st.wall_force / sc.characteristic.F_2star : nan;
        steps.row(
            {st.strain, st.loading ? 1.0 : 0.0, st.width, st.contact_length, double(st.contact_vertices),
             st.volume, st.wall_force / F_star, F2,
             st.bending_energy > 0 ? st.stretch_energy / st.bending_energy : nan, st.core_pressure,
             1 + st.core_pressure * setup.material.s * l / F_star,
             constant_perimeter_ellipse_width(1 - st.strain), elastica ? el.width : nan,
             elastica ? el.contact_length : nan, elastica ? el.volume : nan,
             elastica ? el.force * sc.flexural_rigidity / (F_star * setup.radius * setup.radius) : nan});
        if (!st.loading) continue;
        volume_deviation = std::max(volume_deviation, std::abs(st.volume - (1 - st.strain * st.strain)));
        if (st.strain > 0.3 - 1e-9) {
            eps_late.push_back(st.strain), lc_late.push_back(st.contact_length);
            lc_late_elastica.push_back(el.contact_length);
        }
        if (elastica && st.strain > 0) {
            el_volume_deviation =
                std::max(el_volume_deviation, std::abs(el.volume - (1 - st.strain * st.strain)));
            err_a = std::max(err_a, std::abs(st.width / el.width - 1));
            err_V = std::max(err_V, std::abs(st.volume - el.volume));
            const double F_el = el.force * sc.flexural_rigidity / (setup.radius * setup.radius);
            if (st.strain >= 0.05 - 1e-9) err_F = std::max(err_F, std::abs(st.wall_force / F_el - 1));
            // L_c = N' l0 against the flat length 2c: N' vertices span (N' - 1) l0 (decision
            // spd-Lc-definition).
            if (st.contact_vertices > 0)
                err_Lc = std::max(
                    err_Lc,
                    std::abs((st.contact_vertices - 1) * l - el.contact_length * 2 * setup.radius) / l);
        }
        if (st.contact_vertices > 0) {
            lc_over_l.push_back(st.contact_vertices);
            f_ratio.push_back(plastic ? F2 : st.wall_force / F_star);
        }
    }
    auto& profiles =
        context.table("profiles.dat", {{"eps", "1", "1 - b/b0"},
                                       {"x_over_R", "1", "position from the middle of the contact"},
                                       {"p_over_pstar", "1", "contact force/(s l0) over p* = F*/(s l0)"},
                                       {"p_over_p2star", "1", "over p** = F**/(s l0) (NaN if elastic)"}});
    for (const CompressionState& st : r.states) {
        if (!st.loading) continue;
        const double e10 = std::round(st.strain * 10);
        if (std::abs(st.strain * 10 - e10) > 1e-6 || e10 < 1) continue; // eps = 0.1, 0.2, ...
        for (std::size_t k = 0; k < st.profile_x.size(); ++k)
            profiles.row({st.strain, st.profile_x[k] / setup.radius,
                          st.profile_pressure[k] / sc.characteristic.p_star,
                          plastic ? st.profile_pressure[k] / sc.characteristic.p_2star : NAN});
    }
    // Shapes at eps = 0, 0.1, 0.2, ... (loading and unloading) and after release, closed polygons for
    // plotting.
    auto& shapes = context.table("shapes.dat", {{"eps", "1", "1 - b/b0 (-1: after unloading and release)"},
                                                {"loading", "1", "1 loading, 0 unloading"},
                                                {"x_over_R", "1", "vertex position"},
                                                {"y_over_R", "1", "vertex position"}});
    const auto write_shape = [&](double eps, double loading, const std::vector<double>& x,
                                 const std::vector<double>& y) {
        for (std::size_t k = 0; k <= x.size(); ++k)
            shapes.row({eps, loading, x[k % x.size()] / setup.radius, y[k % x.size()] / setup.radius});
    };
    for (const CompressionState& st : r.states) {
        const double e20 = std::round(st.strain * 20);
        if (std::abs(st.strain * 20 - e20) < 1e-6) write_shape(st.strain, st.loading, st.shape_x, st.shape_y);
    }
    if (unload) write_shape(-1.0, 0.0, r.released_x, r.released_y);
    auto& s = context.summary();
    s["contact_length_slope"] = value_or_null(fit_line_slope(eps_late, lc_late));
    // The symmetric contact gains one vertex at each edge at a time: N' l0 - 2c stays within +-l0 of a
    // constant offset, which bounds the slope's departure from the elastica's.
    s["contact_length_slope_quantisation"] =
        finite_or_null(slope_error_bound(eps_late, l / (2 * setup.radius)));
    s["volume_deviation_max"] = volume_deviation;
    s["force_contact_slope"] = value_or_null(fit_line_slope(lc_over_l, f_ratio));
    s["shape_residual_after_unload"] = unload ? nlohmann::json(r.shape_residual) : nlohmann::json(nullptr);
    const CompressionState* last = nullptr;
    for (const CompressionState& st : r.states)
        if (st.loading) last = &st;
    s["strain_reached"] = last->strain;
    // W_s/W_b and V/V0 at about half the largest strain, to show their growth (Figs. 14, 19).
    for (const CompressionState& st : r.states)
        if (st.loading && st.strain <= 0.5 * last->strain + 1e-9) {
            s["Ws_over_Wb_mid"] = st.bending_energy > 0 ? st.stretch_energy / st.bending_energy : 0.0;
            s["V_over_V0_mid"] = st.volume;
        }
    // The early regime (Fig. 16's first profile, eps = 0.1) and the first contact (Fig. 23: the curves of
    // eta = 0 and inf compared at the same strain and, at small strain steps, the same L_c/l = 1).
    {
        const CompressionState& early = loading_state_nearest(r.states, 0.1);
        const ProfileShape shape = profile_shape(early, l);
        s["eps_early"] = early.strain;
        s["contact_vertices_early"] = early.contact_vertices;
        s["centre_pressure_over_pstar_early"] = shape.centre_pressure / sc.characteristic.p_star;
        s["centre_force_share_early"] = finite_or_null(shape.centre_share);
        const auto first = std::find_if(r.states.begin(), r.states.end(), [](const CompressionState& st) {
            return st.loading && st.contact_vertices > 0;
        });
        if (first != r.states.end()) {
            s["eps_first_contact"] = first->strain;
            s["Lc_over_l_first_contact"] = first->contact_vertices;
            s["F_over_Fstar_first_contact"] = first->wall_force / F_star;
        }
    }
    // Fig. 12: L_c/b0 where the paper puts the onset of faceting (eps = 0.25, L_c = 0.16 b0).
    if (last->strain >= 0.25 - 1e-9)
        s["Lc_over_b0_eps025"] = loading_state_nearest(r.states, 0.25).contact_length;
    // Fig. 15: the paper's F/F* <= L_c/l at every point (eq. (31) as an upper bound).
    {
        double excess = -INFINITY;
        for (std::size_t k = 0; k < lc_over_l.size(); ++k)
            excess = std::max(excess, f_ratio[k] - lc_over_l[k]);
        s["force_contact_excess_max"] = finite_or_null(excess);
    }
    // Shape of the late force growth (Fig. 25): relative second differences of F and of ln F over the
    // loading states nearest to 1/2, 3/4 and 1 of the largest strain; 0 for a linear law (F) or an
    // exponential law (ln F), -0.17 (ln F) for any power law F ~ eps^k over eps = 0.2, 0.3, 0.4.
    {
        const CompressionState *a = &loading_state_nearest(r.states, 0.5 * last->strain),
                               *b = &loading_state_nearest(r.states, 0.75 * last->strain);
        const double Fa = a->wall_force, Fb = b->wall_force, Fc = last->wall_force;
        const bool positive = Fa > 0 && Fb > 0 && Fc > 0 && a != b && b != last;
        s["force_second_difference"] = finite_or_null(positive ? (Fc - 2 * Fb + Fa) / (Fc - Fa) : NAN);
        s["log_force_second_difference"] = finite_or_null(
            positive ? (std::log(Fc) - 2 * std::log(Fb) + std::log(Fa)) / std::log(Fc / Fa) : NAN);
        if (elastica) {
            const double Ea = elastica_ring_between_plates(a->strain).force,
                         Eb = elastica_ring_between_plates(b->strain).force,
                         Ec = elastica_ring_between_plates(last->strain).force;
            s["elastica_force_second_difference"] =
                finite_or_null(positive ? (Ec - 2 * Eb + Ea) / (Ec - Ea) : NAN);
        }
    }
    s["eq35_ratio_final"] = finite_or_null(
        last->contact_vertices > 0
            ? last->wall_force / F_star /
                  ((1 + last->core_pressure * setup.material.s * l / F_star) * last->contact_vertices)
            : NAN);
    s["a_over_b0_final"] = last->width;
    s["Lc_over_b0_final"] = last->contact_length;
    s["V_over_V0_final"] = last->volume;
    s["F_over_Fstar_final"] = last->wall_force / F_star;
    // Undefined (null) for an undeformed ring: both energies vanish, e.g. at strain_max = 4.9e-324.
    s["Ws_over_Wb_final"] =
        finite_or_null(last->bending_energy > 0 ? last->stretch_energy / last->bending_energy : NAN);
    if (elastica) {
        const ElasticaState el = elastica_ring_between_plates(last->strain);
        s["elastica_a_over_b0_final"] = el.width;
        s["elastica_Lc_over_b0_final"] = el.contact_length;
        s["elastica_V_over_V0_final"] = el.volume;
        s["elastica_F_over_Fstar_final"] =
            el.force * sc.flexural_rigidity / (F_star * setup.radius * setup.radius);
    }
    // How the wall force is carried at the last loading state: by the two outermost contact vertices
    // (the elastica: entirely, as two line loads at the edges of the flat) or by a plateau (the paper).
    const ProfileShape final_shape = profile_shape(*last, l);
    s["edge_force_fraction_final"] = finite_or_null(final_shape.edge_share);
    s["edge_zone_force_fraction_final"] = finite_or_null(final_shape.edge_zone_share);
    s["centre_pressure_over_pstar_final"] = final_shape.centre_pressure / sc.characteristic.p_star;
    if (elastica) {
        s["elastica_contact_length_slope"] = value_or_null(fit_line_slope(eps_late, lc_late_elastica));
        s["elastica_volume_deviation_max"] = el_volume_deviation;
        s["elastica_width_error_max"] = err_a;
        s["elastica_volume_error_max"] = err_V;
        s["elastica_force_error_max"] = err_F;
        s["elastica_contact_length_error_max"] = err_Lc;
    }
    s["l0_over_b0"] = l / (2 * setup.radius);
    s["dt"] = r.dt;
    s["dt_critical"] = r.dt_critical;
}

std::vector<ParameterSpec> ring_parameters(std::vector<ParameterSpec> extra)
{
    std::vector<ParameterSpec> ps = {
        ParameterSpec::integer(
            "nodes", 128, "1",
            "vertices N of the ring; 128 keeps F, a/b0 and V/V0 within 1% of the elastica up to "
            "eps = 0.5 (spd-work-precision)")
            .at_least(8),
        ParameterSpec::real("R", 1.0, "m", "initial radius R0").positive(),
        ParameterSpec::real(
            "eta", 0.0, "1",
            "core-to-shell stiffness ratio K_Omega/K_shell, eq. (24); inf: incompressible core "
            "(exact area constraint, the pressure its multiplier)")
            .non_negative()
            .infinity_allowed(),
        ParameterSpec::real("dt_factor", 0.5, "1", "time step over dt_c = sqrt(m/k_max) (section 2.4)")
            .positive(),
    };
    for (auto spec : material_parameters(0.02))
        ps.push_back(spec);
    for (auto& spec : extra)
        ps.push_back(spec);
    return ps;
}

} // namespace

void register_spd_scenes(SceneRegistry& registry)
{
    std::vector<ParameterSpec> beam = {
        ParameterSpec::choice(
            "support", "cantilever", {"cantilever", "simple"},
            "cantilever (clamped at x = 0, force at the tip) or simply supported (force at the centre)"),
        ParameterSpec::integer(
            "nodes", 153, "1",
            "nodes N along the beam (odd for simple support); 153 is the smallest giving both "
            "supports 1% accuracy against beam theory (spd-beam-work-precision)")
            .at_least(3),
        ParameterSpec::real("length", 1.0, "m", "beam length L").positive(),
        ParameterSpec::real("force", 1e-3, "N", "point force F (small: linear theory, delta_max < 0.01 L)")
            .positive(),
        ParameterSpec::real("dt_factor", 0.5, "1", "time step over dt_c = sqrt(m/k_max) (section 2.4)")
            .positive(),
    };
    for (auto spec : material_parameters(0.05))
        beam.push_back(spec);
    const auto ring_memory = [](const Parameters& p) {
        return spd::shell_model_memory(double(p.integer("nodes")), "vertices (nodes)");
    };
    registry.add(
        Scene{"spd.beam",
              "SPD section 3: cantilever or simply supported beam under a point force, against beam theory",
              beam, run_beam}
            .needing([](const Parameters& p) {
                return spd::shell_model_memory(double(p.integer("nodes")), "vertices (nodes)");
            })
            .with_vtk());
    registry.add(Scene{
        "spd.ring_pressure",
        "SPD eqs. (19)-(25): ring under small internal pressure; K_shell and K_e against theory",
        ring_parameters(
            {ParameterSpec::real("pressure", 0.05, "Pa", "applied internal pressure (small)").positive()}),
        run_ring_pressure}
                     .needing(ring_memory)
                     .with_vtk());
    registry.add(Scene{
        "spd.ring_compression",
        "SPD section 4: quasi-static diametral compression of a ring between rigid walls, with the elastica "
        "reference",
        ring_parameters({
            ParameterSpec::real("plastic_ratio", INFINITY, "1", "M_b^Y/M* (eq. (32)); inf: elastic")
                .positive()
                .infinity_allowed(),
            ParameterSpec::real("strain_max", 0.5, "1", "largest strain 1 - b/b0").positive().below(0.85),
            ParameterSpec::real("strain_step", 0.01, "1", "strain increment between relaxations").positive(),
            ParameterSpec::boolean("unload", false, "decompress back to eps = 0 and release the walls"),
            ParameterSpec::real("relax_tolerance", 1e-4, "1",
                                "relaxation criterion: largest unbalanced force over min(EI/R^2, F**)")
                .positive(),
        }),
        run_ring_compression}
                     .needing(ring_memory)
                     .with_vtk());
    register_spd_assembly_scenes(registry);
    register_spd_tissue_scenes(registry);
}

} // namespace softgrain
