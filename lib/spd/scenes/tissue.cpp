// Scene spd.tissue (Trivino et al., section 6, Figs. 30-34): tensile fracture of a cellular tissue.
#include "spd/tissue.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "spd/scenes/scenes.hpp"
#include "spd/shell_model.hpp"
#include "spd/time_step_limits.hpp"
#include "spd/tissue_measures.hpp"
#include "spd/vtk_frames.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::spd {

namespace {

// Fig. 30: the links at set-up.
void write_links(RunContext& context, const Tissue& tissue, double R)
{
    auto& table = context.table("links.dat", {{"x1_over_R", "1", "linked vertex a at set-up"},
                                              {"y1_over_R", "1", "linked vertex a"},
                                              {"x2_over_R", "1", "linked vertex b"},
                                              {"y2_over_R", "1", "linked vertex b"}});
    for (const CohesiveLink& link : tissue.model.links()) {
        const Vec2 a = tissue.model.vertex(link.a) / R, b = tissue.model.vertex(link.b) / R;
        table.row({a.x(), a.y(), b.x(), b.y()});
    }
}

// Figs. 30, 32, 34: set-up, three states during loading (half the peak strain, the peak, halfway from the
// peak to the end) and the end of the run, cells coloured by W/W0.
void write_snapshots(RunContext& context, const PullResult& result, double eps_peak, double R, double W0)
{
    const double eps_end = result.records.back().strain;
    const std::vector<std::size_t> chosen = {
        0, nearest_snapshot(result.snapshots, 0.5 * eps_peak), nearest_snapshot(result.snapshots, eps_peak),
        nearest_snapshot(result.snapshots, 0.5 * (eps_peak + eps_end)), result.snapshots.size() - 1};
    auto& table = context.table(
        "snapshot.dat",
        {{"snapshot", "1",
          "0: set-up, 1-3: during loading (eps_peak/2, eps_peak, halfway to the end), 4: end"},
         {"eps_h", "1", "ln(H/H0) of the snapshot"},
         {"broken_links", "1", "links broken at the snapshot"},
         {"cell", "1", "cell index"},
         {"x_over_R", "1", "vertex position over the mean disk radius (closed polygon)"},
         {"y_over_R", "1", "vertex position"},
         {"W_over_W0", "1", "elastic energy of the cell (stretch + bending) over W0 = (f_n^0)^2/(2 k_n)"}});
    for (std::size_t n = 0; n < chosen.size(); ++n) {
        const TissueSnapshot& snap = result.snapshots[chosen[n]];
        for (std::size_t c = 0; c < snap.cells.size(); ++c)
            for (std::size_t k = 0; k <= snap.cells[c].size(); ++k) {
                const Vec2& x = snap.cells[c][k % snap.cells[c].size()];
                table.row({double(n), snap.strain, double(snap.broken), double(c), x.x() / R, x.y() / R,
                           snap.energy[c] / W0});
            }
    }
}

// The crack: the broken links at the end (positions, forces at breaking).
void write_crack(RunContext& context, const Tissue& tissue, double R)
{
    const ShellModel& model = tissue.model;
    const CohesiveLaw& law = model.link_law();
    auto& table = context.table("broken.dat",
                                {{"x1_over_R", "1", "vertex a of a broken link at the end"},
                                 {"y1_over_R", "1", "vertex a"},
                                 {"x2_over_R", "1", "vertex b"},
                                 {"y2_over_R", "1", "vertex b"},
                                 {"fn_over_fn0", "1", "f_n at breaking over |f_n^0| (compression positive)"},
                                 {"ft_over_ft0", "1", "f_t at breaking over f_t^0"}});
    for (const CohesiveLink& link : model.links())
        if (link.broken) {
            const Vec2 a = model.vertex(link.a), b = model.vertex(link.b);
            table.row({a.x() / R, a.y() / R, b.x() / R, b.y() / R, link.f_n / std::abs(law.f_n0),
                       link.f_t / law.f_t0});
        }
}

// Fig. 31: the zeta = 0 curve of the library (yield_normal_force) over |f_t| <= 2 f_t^0, with zeta evaluated
// on it. Returns max |zeta| (0 up to round-off).
double write_yield_curve(RunContext& context, const CohesiveLaw& law)
{
    auto& table = context.table("yield_curve.dat",
                                {{"ft_over_ft0", "1", "tangential force over f_t^0"},
                                 {"fn_over_fn0", "1", "normal force on zeta = 0 over |f_n^0| (eq. 39)"},
                                 {"zeta", "1", "yield function eq. (39) evaluated on the curve"}});
    double zeta_max = 0;
    for (int k = -200; k <= 200; ++k) {
        const double f_t = 0.01 * k * law.f_t0, f_n = yield_normal_force(f_t, law);
        const double zeta = yield_function(f_n, f_t, law);
        zeta_max = std::max(zeta_max, std::abs(zeta));
        table.row({f_t / law.f_t0, f_n / std::abs(law.f_n0), zeta});
    }
    return zeta_max;
}

// spd.tissue's options: the tissue and the pull.
struct TissueOptions
{
    TissueSetup tissue;
    PullSetup pulling;
};

// The scene's defaults where they differ from the library's.
TissueOptions tissue_defaults()
{
    TissueOptions options;
    options.tissue.columns = 8;
    options.tissue.rows = 10;
    return options;
}

OptionBinding<TissueOptions> tissue_binding()
{
    const auto cells = [](auto... field) { return path(&TissueOptions::tissue, field...); };
    const auto pull = [](auto field) { return path(&TissueOptions::pulling, field); };
    OptionBinding<TissueOptions> binding(tissue_defaults());
    binding.integer(cells(&TissueSetup::columns), "columns", "1", "cells per row (mean disk radius R = 1 m)")
        .at_least(2);
    binding.integer(cells(&TissueSetup::rows), "rows", "1", "rows of cells").at_least(2);
    binding
        .real(cells(&TissueSetup::radius_spread), "radius_spread", "1",
              "Delta R/R of the disks whose radical cells make the tissue")
        .non_negative()
        .below(0.25);
    binding.seed(cells(&TissueSetup::seed), "seed", "seed of the disk radii");
    binding.integer(cells(&TissueSetup::edge_segments), "edge_segments", "1", "shell elements per cell edge")
        .at_least(1);
    binding
        .real(cells(&TissueSetup::vertex_radius), "r", "m",
              "Minkowski radius of the sphero-polygons; neighbouring cells touch at rest "
              "(link rest distance about 2r, decision spd-tissue-shrink)")
        .positive();
    binding
        .real(cells(&TissueSetup::material, &ShellMaterial::h), "h", "m",
              "cell wall thickness (k_s, k_b from eqs. (10)-(11))")
        .positive();
    binding.real(cells(&TissueSetup::eta), "eta", "1", "core-to-shell stiffness ratio, eq. (24)")
        .non_negative();
    binding
        .real(cells(&TissueSetup::plastic_ratio), "plastic_ratio", "1",
              "M_b^Y/M*, eq. (32); inf: elastic cells")
        .positive()
        .infinity_allowed();
    binding
        .real(cells(&TissueSetup::link_stiffness), "link_stiffness", "k_s",
              "k_n of the links over the wall stretch stiffness k_s (decision spd-tissue-parameters)")
        .positive();
    binding
        .real(cells(&TissueSetup::shear_stiffness_ratio), "shear_stiffness_ratio", "1",
              "k_t/k_n of the links (the paper's 'k_n = k_t = 0.1 k_n', decision spd-tissue-kt)")
        .positive();
    binding
        .real(cells(&TissueSetup::cohesion), "cohesion", "F*",
              "|f_n^0|, tensile threshold of eq. (39), over F* = k_b/R")
        .positive();
    binding
        .real(cells(&TissueSetup::shear_strength_ratio), "shear_strength_ratio", "1",
              "f_t^0/|f_n^0| of eq. (39)")
        .positive();
    binding
        .real(cells(&TissueSetup::friction), "friction", "1", "mu of the contact that replaces a broken link")
        .non_negative();
    binding.choice(cells(&TissueSetup::sliding_clamps), "clamps", {{"fixed", false}, {"sliding", true}},
                   "cell edges on the bottom and top lines: fixed (glued), or sliding along the "
                   "walls (vertical component imposed only; decision spd-tissue-clamps)");
    binding
        .real(pull(&PullSetup::pull_rate), "pull_rate", "1/t_c",
              "top-clamp speed over H0, times t_c = sqrt(m/k_s)")
        .positive();
    binding.real(pull(&PullSetup::strain_max), "strain_max", "1", "largest eps_h = ln(H/H0)")
        .positive()
        .below(2.0);
    binding
        .real(pull(&PullSetup::stop_fraction), "stop_fraction", "1",
              "the run stops once no intact path of links joins the clamps and sigma < stop_fraction "
              "sigma_max (0: run to strain_max)")
        .non_negative()
        .below(1.0);
    binding
        .real(pull(&PullSetup::damping), "damping", "2 sqrt(m k_s)",
              "global viscous damping on free vertices")
        .non_negative();
    binding.real(pull(&PullSetup::dt_factor), "dt_factor", "1", "time step over dt_c = sqrt(m/k_max)")
        .positive();
    binding.check([](const TissueOptions& options) {
        const TissueSetup& setup = options.tissue;
        if (setup.material.h >= 0.5 * setup.radius)
            throw InputError("h = " + std::to_string(setup.material.h) +
                             ": the cell wall must be thin against the cell; allowed: h < 0.5 R = 0.5 m");
    });
    return binding;
}

// ParaView frames at every 20th record (100 frames of the 2000 records by default; --vtk-every N: every
// N-th record), the time since the pull started as time value: the cells with W/W0 (Fig. 32) and the
// cohesive links as lines with their forces and broken state, and the contacts (broken links become
// frictional contacts).
PullObserver tissue_frames(RunContext& context, double W0)
{
    return [&context, W0](const Tissue& tissue, double time) {
        if (!context.vtk() || !context.vtk()->next(20)) return;
        const ShellModel& model = tissue.model;
        vtk::PolyData cells = shell_particles(model, tissue.cells);
        std::vector<double> energy;
        for (int cell : tissue.cells)
            energy.push_back(model.elastic_energy(cell) / W0);
        cells.cell_scalars("W_over_W0", std::move(energy));
        vtk::PolyData links;
        std::vector<double> normal, tangential, broken;
        for (const CohesiveLink& link : model.links()) {
            links.add_line({links.add_point(model.vertex(link.a)), links.add_point(model.vertex(link.b))});
            normal.push_back(link.broken ? 0.0 : link.f_n);
            tangential.push_back(link.broken ? 0.0 : link.f_t);
            broken.push_back(link.broken ? 1.0 : 0.0);
        }
        links.cell_scalars("broken", std::move(broken));
        links.cell_scalars("normal_force", std::move(normal));
        links.cell_scalars("tangential_force", std::move(tangential));
        std::vector<vtk::Part> parts{{"particles", std::move(cells)},
                                     {"links", std::move(links)},
                                     {"contacts", shell_contacts(model)}};
        const double H = clamp_height(tissue);
        for (auto& part : parts) {
            part.data.field("strain", std::log(H / tissue.height0));
            part.data.field("force_top", top_clamp_force(tissue));
            part.data.field("broken_links", model.broken_links());
        }
        context.vtk()->write(time, parts);
    };
}

// tissue.dat: the stress-strain curve (Fig. 33) with the broken links and the kinetic energy.
void write_stress_curve(RunContext& context, const TissueSetup& setup, const Tissue& tissue,
                        const PullResult& result, const CurveMeasures& curve)
{
    const TissueScales scales = tissue_scales(setup);
    const double width_depth = tissue.tessellation.width * setup.material.s;
    const double sigma_star = scales.F_star / (2 * setup.radius * setup.material.s); // eq. (37)
    auto& table = context.table(
        "tissue.dat",
        {{"eps_h", "1", "vertical strain ln(H/H0), H between the clamped vertex lines"},
         {"sigma_over_sigmamax", "1", "top-clamp stress F_top/(W s) over its maximum (Fig. 33)"},
         {"sigma_over_sigmastar", "1", "top-clamp stress over sigma* = F*/(2Rs), eq. (37)"},
         {"sigma_bottom_over_sigmamax", "1", "bottom-clamp stress over the top maximum"},
         {"broken_links", "1", "links broken so far"},
         {"kinetic_over_W0", "1", "kinetic energy over W0 = (f_n^0)^2/(2 k_n)"}});
    for (std::size_t k = 0; k < result.records.size(); ++k) {
        const TissueRecord& record = result.records[k];
        table.row({record.strain, curve.sigma[k] / curve.sigma_max, curve.sigma[k] / sigma_star,
                   record.force_bottom / width_depth / curve.sigma_max, double(record.broken),
                   record.kinetic_energy / scales.W0});
    }
}

void write_summary(RunContext& context, const TissueSetup& setup, const Tissue& tissue,
                   const PullResult& result, const CurveMeasures& curve, const LinkStrength& strength,
                   double zeta_max)
{
    const TissueScales scales = tissue_scales(setup);
    const Tessellation& tessellation = tissue.tessellation;
    const double R = setup.radius, W = tessellation.width;
    const double sigma_star = scales.F_star / (2 * R * setup.material.s); // eq. (37)
    const double box_area = W * tessellation.height;
    const CohesiveLaw& law = tissue.model.link_law();
    const Cohesion end = cohesion(tissue);
    const int links = static_cast<int>(tissue.model.links().size());
    const double eps_peak = result.records[curve.peak].strain;
    auto& summary = context.summary();
    summary["yield_curve_zeta_max"] = zeta_max;
    // Fig. 31, one link broken through the model: f_n at a pure-opening break over f_n^0 (eq. (39): 1), and
    // |f_t| at a shear break in compression over eq. (39)'s threshold f_t^0 sqrt(1 + f_n/|f_n^0|) (1), with
    // the displacements that broke them over those of the law (f_n^0/k_n, sqrt(1.5) f_t^0/k_t).
    // A probe that never broke its link is a failed measurement: NaN, written "nan" (not null).
    const LinkBreak& mode_one = strength.mode_one;
    const LinkBreak& shear = strength.shear;
    summary["mode_one_break_fn_over_fn0"] = mode_one.f_n / law.f_n0;
    summary["mode_one_break_ft_over_ft0"] = mode_one.f_t / law.f_t0;
    summary["mode_one_break_opening_over_law"] = mode_one.moved * law.k_n / std::abs(law.f_n0);
    summary["shear_break_fn_over_abs_fn0"] = shear.f_n / std::abs(law.f_n0);
    summary["shear_break_ft_over_threshold"] =
        std::abs(shear.f_t) / (law.f_t0 * std::sqrt(1 + shear.f_n / std::abs(law.f_n0)));
    summary["shear_break_slip_over_law"] = shear.moved * law.k_t / (std::sqrt(1.5) * law.f_t0);
    summary["stress_max"] = curve.sigma_max / sigma_star;
    summary["strain_at_peak"] = eps_peak;
    summary["strain_at_failure"] = finite_or_null(curve.strain_at_failure);
    summary["failure_width_over_peak_strain"] =
        finite_or_null((curve.strain_at_failure - eps_peak) / eps_peak);
    summary["strain_end"] = result.records.back().strain;
    summary["broken_links"] = tissue.model.broken_links();
    summary["links"] = links;
    summary["broken_fraction"] = static_cast<double>(tissue.model.broken_links()) / links;
    summary["broken_links_at_peak"] = result.records[curve.peak].broken;
    summary["separated"] = !end.bottom_to_top;
    summary["crack_height_over_H"] = finite_or_null(crack_height(tissue));
    summary["cell_groups"] = end.groups;
    summary["cracks_crossing"] = end.bottom_to_top ? 0 : end.groups - 1;
    summary["stress_drops"] = curve.drops.size();
    summary["largest_stress_drop"] =
        curve.drops.empty() ? 0.0 : *std::max_element(curve.drops.begin(), curve.drops.end());
    summary["stress_drop_growth"] = finite_or_null(curve.growth);
    const TissueRecord& at_peak = result.records[curve.peak];
    summary["force_mismatch_at_peak"] =
        std::abs(at_peak.force_top - at_peak.force_bottom) / at_peak.force_top;
    summary["cells"] = tissue.cells.size();
    summary["vertices"] = tissue.model.vertices();
    summary["interfaces"] = tissue.interfaces;
    summary["tessellation_area_error"] = std::abs(tessellation.voronoi_area - box_area) / box_area;
    summary["cell_area_error"] = std::abs(total_cell_area(tessellation) - box_area) / box_area;
    summary["merged_corners"] = tessellation.merged_corners;
    summary["W_over_R"] = W / R;
    summary["H0_over_R"] = tissue.height0 / R;
    summary["sigma_star"] = sigma_star;
    summary["W0"] = scales.W0;
    summary["F_star"] = scales.F_star;
    summary["dt"] = result.dt;
    summary["pull_speed_m_per_s"] = result.speed;
}

// The pulled tissue's curve, snapshots, crack, the yield curve of its links, and the summary.
void report_tissue(RunContext& context, const TissueSetup& setup, const Tissue& tissue,
                   const PullResult& result, const LinkStrength& strength)
{
    const CurveMeasures curve = curve_measures(result.records, tissue.tessellation.width * setup.material.s);
    if (!(curve.sigma_max > 0))
        throw NumericalError("tissue stress", result.steps, "the top clamp never pulled: sigma_max = 0");
    write_stress_curve(context, setup, tissue, result, curve);
    write_snapshots(context, result, result.records[curve.peak].strain, setup.radius,
                    tissue_scales(setup).W0);
    write_crack(context, tissue, setup.radius);
    const double zeta_max = write_yield_curve(context, tissue.model.link_law());
    write_summary(context, setup, tissue, result, curve, strength, zeta_max);
}

void run_tissue(const TissueOptions& options, RunContext& context)
{
    const TissueSetup& setup = options.tissue;
    const PullSetup& pulling = options.pulling;
    context.record_seed(setup.seed);

    Tissue tissue = build_tissue(setup);
    write_links(context, tissue, setup.radius); // the set-up, before the pull moves and breaks them
    // Fig. 31: the forces at which the first link breaks, against eq. (39).
    const LinkStrength strength =
        measure_link_strength(tissue, pulling.dt_factor * critical_time_step(tissue.model));
    auto progress = context.progress("spd.tissue");
    const PullResult result = pull(
        tissue, pulling, [&](double fraction) { progress.update(fraction); }, context.checkpoints(),
        tissue_frames(context, tissue_scales(setup).W0));
    progress.finish();
    context.count_steps(result.steps);
    report_tissue(context, setup, tissue, result, strength);
}

} // namespace

Scene tissue_scene()
{
    Scene tissue =
        bound_scene("spd.tissue",
                    "SPD section 6: tensile fracture of a tissue of Laguerre-Voronoi cells joined by "
                    "cohesive links (eq. 39); sigma/sigma_max vs eps_h, broken links, W/W0 snapshots "
                    "(Figs. 30-34)",
                    tissue_binding(), run_tissue);
    tissue.checkpoints = true;
    return std::move(tissue)
        .needing(tissue_binding().estimate([](const TissueOptions& options) {
            // A cell of a planar tiling has 6 edges on average (Euler's formula).
            const TissueSetup& cells = options.tissue;
            return shell_model_memory(double(cells.rows) * double(cells.columns) * 6.0 *
                                          double(cells.edge_segments),
                                      "vertices (rows x columns x 6 x edge_segments)");
        }))
        .with_vtk();
}

} // namespace softgrain::spd
