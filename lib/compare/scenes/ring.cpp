// compare.ring: a thin elastic ring squeezed between two plates by SPD or DPM, against the elastica
// (lib/compare/ring.hpp).
#include "compare/ring.hpp"
#include "compare/scenes/scenes.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/system/system.hpp"
#include "spd/elastica.hpp"
#include "spd/shell_model.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace softgrain::compare {

namespace {

// compare.ring's options: the comparison, its wall thickness given over R.
struct RingOptions
{
    RingComparisonSetup comparison;
    double h_over_R = 0.005;
};

OptionBinding<RingOptions> ring_binding()
{
    const auto comparison = [](auto field) { return path(&RingOptions::comparison, field); };
    OptionBinding<RingOptions> binding;
    binding.choice(
        comparison(&RingComparisonSetup::method), "model",
        {{"spd", RingMethod::spd}, {"dpm", RingMethod::dpm}},
        "spd: SPD eta = 0 ring, damped velocity Verlet; dpm: DPM 2D shell (eq. 9.1, k_a = 0), FIRE");
    binding
        .integer(comparison(&RingComparisonSetup::nodes), "nodes", "1",
                 "vertices N of the ring, a multiple of 4")
        .at_least(8);
    binding.real(comparison(&RingComparisonSetup::radius), "R", "m", "ring radius").positive();
    binding
        .real(comparison(&RingComparisonSetup::E), "E", "Pa",
              "Young modulus: k_s = E h/(1-nu^2), k_b = E h^3/(12(1-nu^2))")
        .positive();
    binding.real(comparison(&RingComparisonSetup::nu), "nu", "1", "Poisson ratio").non_negative().below(0.5);
    binding
        .real(&RingOptions::h_over_R, "h_over_R", "1",
              "wall thickness h/R; sets the extensibility B/(k_s l0 R^2) = (h/R)^2/12 "
              "(decision compare-ring-thickness)")
        .positive()
        .below(0.5);
    binding
        .real(comparison(&RingComparisonSetup::dt_factor), "dt_factor", "1",
              "spd only: time step over dt_c = sqrt(m/k_max); dpm: FIRE's own adaptive step")
        .positive();
    binding.real(comparison(&RingComparisonSetup::strain_max), "strain_max", "1", "largest strain 1 - b/b0")
        .positive()
        .below(0.85);
    binding
        .real(comparison(&RingComparisonSetup::strain_step), "strain_step", "1",
              "strain increment between relaxations, 0.1/k")
        .positive();
    binding
        .real(comparison(&RingComparisonSetup::relax_tolerance), "relax_tolerance", "1",
              "relaxation criterion: largest unbalanced force over B/R^2 (decision "
              "compare-ring-relaxation)")
        .positive();
    return binding;
}

// "eps03" for eps = 0.3: the summary-key suffix of a strain that is a multiple of 0.1.
std::string strain_key(double eps)
{
    return "eps0" + std::to_string(std::lround(10 * eps));
}

// ring.dat: every recorded state beyond eps = 0 against the elastica.
void write_ring_table(const RingComparison& result, RunContext& context)
{
    auto& table = context.table(
        "ring.dat",
        {{"eps", "1", "strain 1 - b/b0 (b: plate gap of the mid-line)"},
         {"F_R2_over_B", "1", "force on one plate F R^2/B, B = k_b l0"},
         {"a_over_b0", "1", "width a/b0"},
         {"V_over_V0", "1", "area ratio"},
         {"Lc_over_b0", "1", "distance between the outermost vertices touching the top plate, over b0"},
         {"elastica_F_R2_over_B", "1", "inextensible elastica (lib/spd/elastica.hpp)"},
         {"elastica_a_over_b0", "1", "elastica"},
         {"elastica_V_over_V0", "1", "elastica"},
         {"elastica_Lc_over_b0", "1", "elastica flat length 2c/b0"},
         {"force_error", "1", "|F/F_elastica - 1|"},
         {"width_error", "1", "|a/a_elastica - 1|"},
         {"volume_error", "1", "|V/V0 - elastica|"},
         {"contact_length_error", "1", "|L_c - 2c|/b0"}});
    for (const RingObservation& state : result.states) {
        if (state.strain <= 0) continue;
        const spd::ElasticaState elastica = spd::elastica_ring_between_plates(state.strain);
        const RingErrors errors = elastica_errors(state);
        table.row({state.strain, state.force, state.width, state.volume, state.contact_length, elastica.force,
                   elastica.width, elastica.volume, elastica.contact_length, errors.force, errors.width,
                   errors.volume, errors.contact_length});
    }
}

void write_summary(const RingOptions& options, const RingComparison& result, RunContext& context)
{
    const RingComparisonSetup& setup = options.comparison;
    auto& summary = context.summary();
    // The observables at eps = 0.1, 0.2, ...
    for (const RingObservation& state : result.states) {
        if (!reported_strain(state.strain)) continue;
        const RingErrors errors = elastica_errors(state);
        const std::string key = strain_key(state.strain);
        summary["F_R2_over_B_" + key] = state.force;
        summary["force_error_" + key] = errors.force;
        summary["width_error_" + key] = errors.width;
        summary["volume_error_" + key] = errors.volume;
        summary["contact_length_error_" + key] = errors.contact_length;
    }
    // Small-strain stiffness: F R^2/B over eps at the first increment, and the linear ring theory
    // F R^2/B = 2 eps/(pi/4 - 2/pi) (diametral point loads).
    const RingObservation& first = result.states.at(1);
    summary["force_slope_first_step"] = first.force / first.strain;
    summary["elastica_force_slope_first_step"] =
        spd::elastica_ring_between_plates(first.strain).force / first.strain;
    summary["linear_theory_force_slope"] = 2 / (std::numbers::pi / 4 - 2 / std::numbers::pi);
    // null when no state lies at eps = 0.1, 0.2, ... (strain_max < 0.1).
    const std::optional<RingErrors> worst = largest_elastica_errors(result);
    const auto if_observed = [&worst](double RingErrors::*error) {
        return worst ? nlohmann::json((*worst).*error) : nlohmann::json(nullptr);
    };
    summary["force_error_max"] = if_observed(&RingErrors::force);
    summary["width_error_max"] = if_observed(&RingErrors::width);
    summary["volume_error_max"] = if_observed(&RingErrors::volume);
    summary["contact_length_error_max"] = if_observed(&RingErrors::contact_length);
    summary["method_index"] = setup.method == RingMethod::spd ? 0 : 1;
    summary["strain_reached"] = result.states.back().strain;
    summary["bending_rigidity"] = result.bending_rigidity;
    summary["l0_over_R"] = 2 * std::sin(std::numbers::pi / setup.nodes);
    summary["stretch_over_bending_stiffness"] = std::pow(options.h_over_R, 2) / 12; // B/(k_s l0 R^2)
    summary["iterations"] = result.steps;
    summary["dt_over_dt_critical"] = finite_or_null(result.dt / result.dt_critical);
    summary["dt_stable_over_dt_critical"] = finite_or_null(result.dt_stable / result.dt_critical);
}

void run_ring(const RingOptions& options, RunContext& context)
{
    RingComparisonSetup setup = options.comparison;
    setup.h = options.h_over_R * setup.radius;
    auto progress = context.progress("compare.ring");
    // ParaView frames, one per recorded strain (eps = 0 and each increment; --vtk-every N: every N-th), time
    // value eps: the model's own datasets (RingFrameObserver), field data strain and F R^2/B.
    RingFrameObserver frame;
    if (context.vtk())
        frame = [&](const RingObservation& observation, std::vector<vtk::Part> parts) {
            if (!context.vtk()->next()) return;
            for (vtk::Part& part : parts) {
                part.data.field("strain", observation.strain);
                part.data.field("F_R2_over_B", observation.force);
            }
            context.vtk()->write(observation.strain, parts);
        };
    const RingComparison result = compress_ring(
        setup, [&](double fraction) { progress.update(fraction); }, frame);
    progress.finish();
    context.count_steps(result.steps);
    write_ring_table(result, context);
    write_summary(options, result, context);
}

} // namespace

Scene ring_scene()
{
    return bound_scene("compare.ring",
                       "a thin elastic ring squeezed between two plates by SPD or DPM, against the elastica",
                       ring_binding(), run_ring)
        .advised_by({"compare",
                     "compare-ring-work-precision",
                     "method_index",
                     {"spd", "dpm"},
                     "dt_factor",
                     "spd",
                     "nodes",
                     "vertices N of the ring",
                     "force_error_max",
                     "largest |F/F_elastica - 1| over eps = 0.1 ... 0.6 (h/R = 0.005)"})
        .needing(ring_binding().estimate([](const RingOptions& options) {
            const double n = options.comparison.nodes;
            return options.comparison.method == RingMethod::spd
                       ? spd::shell_model_memory(n, "vertices (nodes)")
                       : dpm::dpm_vertex_memory(n, "vertices (nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::compare
