// spd.ring_compression (Trivino et al., section 4, Figs. 10-25): quasi-static diametral compression of a
// ring between rigid walls, and optionally its unloading, with the elastica as the reference.
#include "core/output.hpp"
#include "spd/compression_measures.hpp"
#include "spd/elastica.hpp"
#include "spd/ring.hpp"
#include "spd/scenes/parameters.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/vtk_frames.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace softgrain::spd {

namespace {

// spd.ring_compression's options: the ring and the loading protocol of spd::ring_compression.
struct RingCompressionOptions
{
    RingSetup ring;
    double strain_max = 0.5, strain_step = 0.01;
    bool unload = false;
    double relax_tolerance = 1e-4;
};

OptionBinding<RingCompressionOptions> ring_compression_binding()
{
    OptionBinding<RingCompressionOptions> binding;
    bind_ring(binding, &RingCompressionOptions::ring);
    binding
        .real(path(&RingCompressionOptions::ring, &RingSetup::plastic_ratio), "plastic_ratio", "1",
              "M_b^Y/M* (eq. (32)); inf: elastic")
        .positive()
        .infinity_allowed();
    binding.real(&RingCompressionOptions::strain_max, "strain_max", "1", "largest strain 1 - b/b0")
        .positive()
        .below(0.85);
    binding
        .real(&RingCompressionOptions::strain_step, "strain_step", "1",
              "strain increment between relaxations")
        .positive();
    binding.boolean(&RingCompressionOptions::unload, "unload",
                    "decompress back to eps = 0 and release the walls");
    binding
        .real(&RingCompressionOptions::relax_tolerance, "relax_tolerance", "1",
              "relaxation criterion: largest unbalanced force over min(EI/R^2, F**)")
        .positive();
    return binding;
}

bool is_elastic(const RingSetup& setup)
{
    return !std::isfinite(setup.plastic_ratio);
}

// W_s/W_b, NaN for an undeformed ring (both energies vanish).
double stretch_over_bending(const CompressionState& state)
{
    return state.bending_energy > 0 ? state.stretch_energy / state.bending_energy : NAN;
}

// compression.dat: every recorded state, with eq. (26) and the elastica at the same strain.
void write_compression_table(const RingSetup& setup, const CompressionResult& result, RunContext& context)
{
    const RingScales scales = ring_scales(setup);
    const double F_star = scales.characteristic.F_star, R = setup.radius;
    const bool plastic = !is_elastic(setup), elastica = elastica_applies(setup);
    auto& table = context.table(
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
    for (const CompressionState& state : result.states) {
        const ElasticaState reference =
            elastica ? elastica_ring_between_plates(state.strain) : ElasticaState{};
        const double nan = NAN;
        table.row({state.strain, state.loading ? 1.0 : 0.0, state.width, state.contact_length,
                   double(state.contact_vertices), state.volume, state.wall_force / F_star,
                   plastic ? state.wall_force / scales.characteristic.F_2star : nan,
                   stretch_over_bending(state), state.core_pressure,
                   1 + state.core_pressure * setup.material.s * scales.l0 / F_star,
                   constant_perimeter_ellipse_width(1 - state.strain), elastica ? reference.width : nan,
                   elastica ? reference.contact_length : nan, elastica ? reference.volume : nan,
                   elastica ? reference.force * scales.flexural_rigidity / (F_star * R * R) : nan});
    }
}

// profiles.dat: the contact pressure along the top wall at eps = 0.1, 0.2, ... while loading.
void write_profiles(const RingSetup& setup, const CompressionResult& result, RunContext& context)
{
    const RingScales scales = ring_scales(setup);
    const bool plastic = !is_elastic(setup);
    auto& profiles =
        context.table("profiles.dat", {{"eps", "1", "1 - b/b0"},
                                       {"x_over_R", "1", "position from the middle of the contact"},
                                       {"p_over_pstar", "1", "contact force/(s l0) over p* = F*/(s l0)"},
                                       {"p_over_p2star", "1", "over p** = F**/(s l0) (NaN if elastic)"}});
    for (const CompressionState& state : result.states) {
        if (!state.loading) continue;
        const double tenths = std::round(state.strain * 10);
        if (std::abs(state.strain * 10 - tenths) > 1e-6 || tenths < 1) continue;
        for (std::size_t k = 0; k < state.profile_x.size(); ++k)
            profiles.row({state.strain, state.profile_x[k] / setup.radius,
                          state.profile_pressure[k] / scales.characteristic.p_star,
                          plastic ? state.profile_pressure[k] / scales.characteristic.p_2star : NAN});
    }
}

// shapes.dat: the ring at eps = 0, 0.05, 0.1, ... (loading and unloading) and after the release, closed
// polygons for plotting.
void write_shapes(const RingSetup& setup, const CompressionResult& result, bool unload, RunContext& context)
{
    auto& shapes = context.table("shapes.dat", {{"eps", "1", "1 - b/b0 (-1: after unloading and release)"},
                                                {"loading", "1", "1 loading, 0 unloading"},
                                                {"x_over_R", "1", "vertex position"},
                                                {"y_over_R", "1", "vertex position"}});
    const auto write_shape = [&](double eps, double loading, const std::vector<double>& x,
                                 const std::vector<double>& y) {
        for (std::size_t k = 0; k <= x.size(); ++k)
            shapes.row({eps, loading, x[k % x.size()] / setup.radius, y[k % x.size()] / setup.radius});
    };
    for (const CompressionState& state : result.states) {
        const double twentieths = std::round(state.strain * 20);
        if (std::abs(state.strain * 20 - twentieths) < 1e-6)
            write_shape(state.strain, state.loading, state.shape_x, state.shape_y);
    }
    if (unload) write_shape(-1.0, 0.0, result.released_x, result.released_y);
}

void write_summary(const RingSetup& setup, const CompressionResult& result,
                   const CompressionMeasures& measures, bool unload, RunContext& context)
{
    const RingScales scales = ring_scales(setup);
    const double F_star = scales.characteristic.F_star, p_star = scales.characteristic.p_star;
    const double R = setup.radius;
    const CompressionState& last = measures.final;
    auto& summary = context.summary();
    summary["contact_length_slope"] = value_or_null(measures.contact_length_slope);
    summary["contact_length_slope_quantisation"] = finite_or_null(measures.contact_length_slope_quantisation);
    summary["volume_deviation_max"] = measures.volume_deviation_max;
    summary["force_contact_slope"] = value_or_null(measures.force_contact_slope);
    summary["shape_residual_after_unload"] =
        unload ? nlohmann::json(result.shape_residual) : nlohmann::json(nullptr);
    summary["strain_reached"] = last.strain;
    const CompressionState& middle = measures.middle;
    summary["Ws_over_Wb_mid"] =
        middle.bending_energy > 0 ? middle.stretch_energy / middle.bending_energy : 0.0;
    summary["V_over_V0_mid"] = middle.volume;
    summary["eps_early"] = measures.early.strain;
    summary["contact_vertices_early"] = measures.early.contact_vertices;
    summary["centre_pressure_over_pstar_early"] = measures.early_profile.centre_pressure / p_star;
    summary["centre_force_share_early"] = finite_or_null(measures.early_profile.centre_share);
    if (measures.first_contact) {
        summary["eps_first_contact"] = measures.first_contact->strain;
        summary["Lc_over_l_first_contact"] = measures.first_contact->contact_vertices;
        summary["F_over_Fstar_first_contact"] = measures.first_contact->wall_force / F_star;
    }
    if (measures.contact_length_eps025) summary["Lc_over_b0_eps025"] = *measures.contact_length_eps025;
    summary["force_contact_excess_max"] = finite_or_null(measures.force_contact_excess_max);
    summary["force_second_difference"] = finite_or_null(measures.force_second_difference);
    summary["log_force_second_difference"] = finite_or_null(measures.log_force_second_difference);
    summary["eq35_ratio_final"] = finite_or_null(measures.eq35_ratio_final);
    summary["a_over_b0_final"] = last.width;
    summary["Lc_over_b0_final"] = last.contact_length;
    summary["V_over_V0_final"] = last.volume;
    summary["F_over_Fstar_final"] = last.wall_force / F_star;
    // Undefined (null) for an undeformed ring, e.g. at strain_max = 4.9e-324.
    summary["Ws_over_Wb_final"] = finite_or_null(stretch_over_bending(last));
    // How the wall force is carried at the last loading state: by the two outermost contact vertices
    // (the elastica: entirely, as two line loads at the edges of the flat) or by a plateau (the paper).
    summary["edge_force_fraction_final"] = finite_or_null(measures.final_profile.edge_share);
    summary["edge_zone_force_fraction_final"] = finite_or_null(measures.final_profile.edge_zone_share);
    summary["centre_pressure_over_pstar_final"] = measures.final_profile.centre_pressure / p_star;
    if (const auto& elastica = measures.elastica) {
        summary["elastica_force_second_difference"] = finite_or_null(elastica->force_second_difference);
        summary["elastica_a_over_b0_final"] = elastica->final.width;
        summary["elastica_Lc_over_b0_final"] = elastica->final.contact_length;
        summary["elastica_V_over_V0_final"] = elastica->final.volume;
        summary["elastica_F_over_Fstar_final"] =
            elastica->final.force * scales.flexural_rigidity / (F_star * R * R);
        summary["elastica_contact_length_slope"] = value_or_null(elastica->contact_length_slope);
        summary["elastica_volume_deviation_max"] = elastica->volume_deviation_max;
        summary["elastica_width_error_max"] = elastica->width_error_max;
        summary["elastica_volume_error_max"] = elastica->volume_error_max;
        summary["elastica_force_error_max"] = elastica->force_error_max;
        summary["elastica_contact_length_error_max"] = elastica->contact_length_error_max;
    }
    summary["l0_over_b0"] = scales.l0 / (2 * R);
    summary["dt"] = result.dt;
    summary["dt_critical"] = result.dt_critical;
}

void run_ring_compression(const RingCompressionOptions& options, RunContext& context)
{
    const RingSetup& setup = options.ring;
    auto progress = context.progress("spd.ring_compression");
    // ParaView frames: one per recorded load step, the step's index as the time value (the strain goes back
    // down on unloading) and the strain as field data.
    std::int64_t load_step = 0;
    const auto frame = [&](const RingBetweenWalls& walls, const CompressionState& state) {
        if (context.vtk() && context.vtk()->due(load_step))
            context.vtk()->write(static_cast<double>(load_step),
                                 shell_frame(walls.model, {walls.ring}, {walls.bottom_wall, walls.top_wall},
                                             {{"load_step", static_cast<double>(load_step)},
                                              {"strain", state.strain},
                                              {"loading", state.loading ? 1.0 : 0.0}}));
        ++load_step;
    };
    const CompressionResult result = ring_compression(
        setup, options.strain_max, options.strain_step, options.unload, options.relax_tolerance,
        [&](double fraction) { progress.update(fraction); }, frame);
    progress.finish();
    context.count_steps(result.steps);

    write_compression_table(setup, result, context);
    write_profiles(setup, result, context);
    write_shapes(setup, result, options.unload, context);
    write_summary(setup, result, measure_compression(setup, result), options.unload, context);
}

} // namespace

Scene ring_compression_scene()
{
    return bound_scene(
               "spd.ring_compression",
               "SPD section 4: quasi-static diametral compression of a ring between rigid walls, with "
               "the elastica reference",
               ring_compression_binding(), run_ring_compression)
        .needing(ring_compression_binding().estimate([](const RingCompressionOptions& options) {
            return shell_model_memory(options.ring.nodes, "vertices (nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::spd
