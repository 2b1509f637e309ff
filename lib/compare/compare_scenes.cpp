// Scenes of the cross-method comparisons (DESIGN.md, "one scene, several methods").
#include "compare/compare_scenes.hpp"

#include "compare/ring.hpp"
#include "core/output.hpp"
#include "dpm/system.hpp"
#include "spd/elastica.hpp"
#include "spd/shell_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace softgrain {

namespace {
using namespace compare;

// "eps03" for eps = 0.3: the summary-key suffix of a strain that is a multiple of 0.1.
std::string strain_key(double eps)
{
    return "eps0" + std::to_string(std::lround(10 * eps));
}

void run_ring(const Parameters& p, RunContext& context)
{
    RingComparisonSetup setup;
    setup.method = ring_method_from_name(p.choice("model"));
    setup.nodes = static_cast<int>(p.integer("nodes"));
    setup.radius = p.real("R");
    setup.E = p.real("E");
    setup.nu = p.real("nu");
    setup.h = p.real("h_over_R") * setup.radius;
    setup.dt_factor = p.real("dt_factor");
    setup.strain_max = p.real("strain_max");
    setup.strain_step = p.real("strain_step");
    setup.relax_tolerance = p.real("relax_tolerance");
    auto progress = context.progress("compare.ring");
    // ParaView frames, one per recorded strain (eps = 0 and each increment; --vtk-every N: every N-th), time
    // value eps: the model's own datasets (RingFrameObserver), field data strain and F R^2/B.
    RingFrameObserver frame;
    if (context.vtk())
        frame = [&](const RingObservation& o, std::vector<vtk::Part> parts) {
            if (!context.vtk()->next()) return;
            for (vtk::Part& part : parts) {
                part.data.field("strain", o.strain);
                part.data.field("F_R2_over_B", o.force);
            }
            context.vtk()->write(o.strain, parts);
        };
    const RingComparison r = compress_ring(
        setup, [&](double f) { progress.update(f); }, frame);
    progress.finish();
    context.count_steps(r.steps);

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
    RingErrors worst;
    bool observed = false; // a state at eps = 0.1, 0.2, ... (none when strain_max < 0.1)
    auto& s = context.summary();
    for (const RingObservation& o : r.states) {
        if (o.strain <= 0) continue;
        const spd::ElasticaState el = spd::elastica_ring_between_plates(o.strain);
        const RingErrors e = elastica_errors(o);
        table.row({o.strain, o.force, o.width, o.volume, o.contact_length, el.force, el.width, el.volume,
                   el.contact_length, e.force, e.width, e.volume, e.contact_length});
        const double tenths = 10 * o.strain;
        if (std::abs(tenths - std::round(tenths)) > 1e-6) continue; // the observables at eps = 0.1, 0.2, ...
        observed = true;
        worst = {std::max(worst.force, e.force), std::max(worst.width, e.width),
                 std::max(worst.volume, e.volume), std::max(worst.contact_length, e.contact_length)};
        const std::string key = strain_key(o.strain);
        s["F_R2_over_B_" + key] = o.force;
        s["force_error_" + key] = e.force;
        s["width_error_" + key] = e.width;
        s["volume_error_" + key] = e.volume;
        s["contact_length_error_" + key] = e.contact_length;
    }
    // Small-strain stiffness: F R^2/B over eps at the first increment, and the linear ring theory
    // F R^2/B = 2 eps/(pi/4 - 2/pi) (diametral point loads).
    const RingObservation& first = r.states.at(1);
    s["force_slope_first_step"] = first.force / first.strain;
    s["elastica_force_slope_first_step"] =
        spd::elastica_ring_between_plates(first.strain).force / first.strain;
    s["linear_theory_force_slope"] = 2 / (std::numbers::pi / 4 - 2 / std::numbers::pi);
    const auto if_observed = [observed](double v) {
        return observed ? nlohmann::json(v) : nlohmann::json(nullptr);
    };
    s["force_error_max"] = if_observed(worst.force);
    s["width_error_max"] = if_observed(worst.width);
    s["volume_error_max"] = if_observed(worst.volume);
    s["contact_length_error_max"] = if_observed(worst.contact_length);
    s["method_index"] = setup.method == RingMethod::spd ? 0 : 1;
    s["strain_reached"] = r.states.back().strain;
    s["bending_rigidity"] = r.bending_rigidity;
    s["l0_over_R"] = 2 * std::sin(std::numbers::pi / setup.nodes);
    s["stretch_over_bending_stiffness"] = std::pow(p.real("h_over_R"), 2) / 12; // B/(k_s l0 R^2)
    s["iterations"] = r.steps;
    s["dt_over_dt_critical"] = finite_or_null(r.dt / r.dt_critical);
    s["dt_stable_over_dt_critical"] = finite_or_null(r.dt_stable / r.dt_critical);
}

} // namespace

void register_compare_scenes(SceneRegistry& registry)
{
    std::vector<ParameterSpec> ring = {
        ParameterSpec::choice("model", "spd", {"spd", "dpm"},
                              "spd: SPD eta = 0 ring, damped velocity Verlet; dpm: DPM 2D shell (eq. 9.1, "
                              "k_a = 0), FIRE"),
        ParameterSpec::integer("nodes", 128, "1", "vertices N of the ring, a multiple of 4").at_least(8),
        ParameterSpec::real("R", 1.0, "m", "ring radius").positive(),
        ParameterSpec::real("E", 1e6, "Pa", "Young modulus: k_s = E h/(1-nu^2), k_b = E h^3/(12(1-nu^2))")
            .positive(),
        ParameterSpec::real("nu", 0.3, "1", "Poisson ratio").non_negative().below(0.5),
        ParameterSpec::real("h_over_R", 0.005, "1",
                            "wall thickness h/R; sets the extensibility B/(k_s l0 R^2) = (h/R)^2/12 "
                            "(decision compare-ring-thickness)")
            .positive()
            .below(0.5),
        ParameterSpec::real("dt_factor", 0.5, "1",
                            "spd only: time step over dt_c = sqrt(m/k_max); dpm: FIRE's own adaptive step")
            .positive(),
        ParameterSpec::real("strain_max", 0.6, "1", "largest strain 1 - b/b0").positive().below(0.85),
        ParameterSpec::real("strain_step", 0.05, "1", "strain increment between relaxations, 0.1/k")
            .positive(),
        ParameterSpec::real("relax_tolerance", 1e-5, "1",
                            "relaxation criterion: largest unbalanced force over B/R^2 (decision "
                            "compare-ring-relaxation)")
            .positive(),
    };
    registry.add(Scene{"compare.ring",
                       "a thin elastic ring squeezed between two plates by SPD or DPM, against the elastica",
                       ring, run_ring}
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
                     .needing([](const Parameters& p) {
                         const double n = static_cast<double>(p.integer("nodes"));
                         return p.choice("model") == "spd" ? spd::shell_model_memory(n, "vertices (nodes)")
                                                           : dpm::dpm_vertex_memory(n, "vertices (nodes)");
                     })
                     .with_vtk());
}

} // namespace softgrain
