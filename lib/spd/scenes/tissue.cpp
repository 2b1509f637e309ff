// Scene spd.tissue (Trivino et al., section 6, Figs. 30-34): tensile fracture of a cellular tissue.
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "spd/shell_model.hpp"
#include "spd/spd_scenes.hpp"
#include "spd/tissue.hpp"
#include "spd/vtk_frames.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain {

namespace {
using namespace spd;

// Stress drops (decision spd-tissue-measures): sigma falls by more than `threshold` from a running maximum
// before it rises by `threshold` above the running minimum; a drop's size is maximum - minimum.
std::vector<double> stress_drops(const std::vector<double>& sigma, double threshold)
{
    std::vector<double> drops;
    double high = sigma.front(), low = sigma.front();
    bool falling = false;
    for (double s : sigma) {
        if (!falling) {
            high = std::max(high, s);
            if (s < high - threshold) falling = true, low = s;
        } else {
            low = std::min(low, s);
            if (s > low + threshold) {
                drops.push_back(high - low);
                falling = false;
                high = s;
            }
        }
    }
    if (falling) drops.push_back(high - low);
    return drops;
}

// The stored snapshot closest in strain to `strain`.
std::size_t nearest_snapshot(const std::vector<TissueSnapshot>& snaps, double strain)
{
    std::size_t best = 0;
    for (std::size_t k = 0; k < snaps.size(); ++k)
        if (std::abs(snaps[k].strain - strain) < std::abs(snaps[best].strain - strain)) best = k;
    return best;
}

// The measures of Fig. 33 on the recorded curve (decision spd-tissue-measures): sigma = F_top/(W s), its
// peak, the failure strain (first record after the peak below 0.1 sigma_max), the stress drops of more than
// 0.05 sigma_max and the growth of their size (later half over earlier half).
struct CurveMeasures
{
    std::vector<double> sigma; // [Pa]
    double sigma_max = 0;
    std::size_t peak = 0;
    double strain_at_failure = NAN;
    std::vector<double> drops; // [sigma_max]
    double growth = NAN;
};
CurveMeasures curve_measures(const std::vector<TissueRecord>& records, double width_depth)
{
    CurveMeasures m;
    for (std::size_t k = 0; k < records.size(); ++k) {
        m.sigma.push_back(records[k].force_top / width_depth);
        if (m.sigma.back() > m.sigma_max) m.sigma_max = m.sigma.back(), m.peak = k;
    }
    for (std::size_t k = m.peak; k < records.size(); ++k)
        if (m.sigma[k] < 0.1 * m.sigma_max) {
            m.strain_at_failure = records[k].strain;
            break;
        }
    std::vector<double> normalised;
    for (double s : m.sigma)
        normalised.push_back(s / m.sigma_max);
    m.drops = stress_drops(normalised, 0.05);
    if (m.drops.size() >= 2) {
        const std::size_t half = m.drops.size() / 2;
        double first = 0, second = 0;
        for (std::size_t k = 0; k < m.drops.size(); ++k)
            (k < half ? first : second) += m.drops[k];
        m.growth =
            (second / static_cast<double>(m.drops.size() - half)) / (first / static_cast<double>(half));
    }
    return m;
}

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
void write_snapshots(RunContext& context, const PullResult& r, double eps_peak, double R, double W0)
{
    const double eps_end = r.records.back().strain;
    const std::vector<std::size_t> chosen = {
        0, nearest_snapshot(r.snapshots, 0.5 * eps_peak), nearest_snapshot(r.snapshots, eps_peak),
        nearest_snapshot(r.snapshots, 0.5 * (eps_peak + eps_end)), r.snapshots.size() - 1};
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
        const TissueSnapshot& snap = r.snapshots[chosen[n]];
        for (std::size_t c = 0; c < snap.cells.size(); ++c)
            for (std::size_t k = 0; k <= snap.cells[c].size(); ++k) {
                const Vec2& x = snap.cells[c][k % snap.cells[c].size()];
                table.row({double(n), snap.strain, double(snap.broken), double(c), x.x() / R, x.y() / R,
                           snap.energy[c] / W0});
            }
    }
}

// The crack: the broken links at the end (positions, forces at breaking). Returns the mean height of the
// broken links above the bottom clamp over H (NaN without any).
double write_crack(RunContext& context, const Tissue& tissue, double R)
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
    const double y_bottom = model.vertex(tissue.bottom.front()).y(), H = clamp_height(tissue);
    double height = 0;
    for (const CohesiveLink& link : model.links())
        if (link.broken) {
            const Vec2 a = model.vertex(link.a), b = model.vertex(link.b);
            height += (0.5 * (a.y() + b.y()) - y_bottom) / H;
            table.row({a.x() / R, a.y() / R, b.x() / R, b.y() / R, link.f_n / std::abs(law.f_n0),
                       link.f_t / law.f_t0});
        }
    return height / model.broken_links();
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

// Fig. 31: one link of the built tissue, loaded through the model's own force evaluation
// (ShellModel::compute_forces, which tests eq. (39) and breaks the link): both vertices of its cell-j side
// (b and b' for an opening, b alone for a slip) are first moved by `approach` along -n (closing, f_n > 0),
// then step by step by `increment` along `direction` (n: opening, t: slip) until the link breaks. Returns the
// link's f_n, f_t at the break and the distance moved in `direction` (NaN if it never broke in 20000 steps or
// the model stopped with a numerical failure).
struct LinkBreak
{
    double f_n = NAN, f_t = NAN, moved = NAN;
};
LinkBreak break_one_link(ShellModel model, std::size_t index, double approach, bool opening, double increment,
                         double dt)
{
    // Opening moves b and b' (the frame stays); a slip of f_t^0/k_t ~ 0.4 m would carry b' past the end of
    // the interface into the next cell, so a slip moves b alone, along t into the interface (m moves along
    // t: the frame stays; the approach turns it by approach/(2 |m' - m|) ~ 1e-2, which the measured f_n, f_t
    // at the break include).
    const CohesiveLink link = model.links()[index];
    const LinkKinematics k = link_kinematics(link, model.vertex(link.a), model.vertex(link.b),
                                             model.vertex(link.partner_a), model.vertex(link.partner_b));
    const Vec2 direction = opening ? k.n : k.t;
    const Vec2 b = model.vertex(link.b) - approach * k.n, pb = model.vertex(link.partner_b);
    try {
        for (int step = 0; step <= 20000; ++step) {
            model.set_vertex(link.b, b + step * increment * direction);
            if (opening) model.set_vertex(link.partner_b, pb + step * increment * direction);
            model.compute_forces(dt);
            const CohesiveLink& now = model.links()[index];
            if (now.broken) return {now.f_n, now.f_t, step * increment};
        }
    } catch (const NumericalError&) { // e.g. the contact law refusing the overlap: reported as no break (NaN)
    }
    return {};
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
    OptionBinding<TissueOptions> b(tissue_defaults());
    b.integer(cells(&TissueSetup::columns), "columns", "1", "cells per row (mean disk radius R = 1 m)")
        .at_least(2);
    b.integer(cells(&TissueSetup::rows), "rows", "1", "rows of cells").at_least(2);
    b.real(cells(&TissueSetup::radius_spread), "radius_spread", "1",
           "Delta R/R of the disks whose radical cells make the tissue")
        .non_negative()
        .below(0.25);
    b.seed(cells(&TissueSetup::seed), "seed", "seed of the disk radii");
    b.integer(cells(&TissueSetup::edge_segments), "edge_segments", "1", "shell elements per cell edge")
        .at_least(1);
    b.real(cells(&TissueSetup::vertex_radius), "r", "m",
           "Minkowski radius of the sphero-polygons; neighbouring cells touch at rest "
           "(link rest distance about 2r, decision spd-tissue-shrink)")
        .positive();
    b.real(cells(&TissueSetup::material, &ShellMaterial::h), "h", "m",
           "cell wall thickness (k_s, k_b from eqs. (10)-(11))")
        .positive();
    b.real(cells(&TissueSetup::eta), "eta", "1", "core-to-shell stiffness ratio, eq. (24)").non_negative();
    b.real(cells(&TissueSetup::plastic_ratio), "plastic_ratio", "1", "M_b^Y/M*, eq. (32); inf: elastic cells")
        .positive()
        .infinity_allowed();
    b.real(cells(&TissueSetup::link_stiffness), "link_stiffness", "k_s",
           "k_n of the links over the wall stretch stiffness k_s (decision spd-tissue-parameters)")
        .positive();
    b.real(cells(&TissueSetup::shear_stiffness_ratio), "shear_stiffness_ratio", "1",
           "k_t/k_n of the links (the paper's 'k_n = k_t = 0.1 k_n', decision spd-tissue-kt)")
        .positive();
    b.real(cells(&TissueSetup::cohesion), "cohesion", "F*",
           "|f_n^0|, tensile threshold of eq. (39), over F* = k_b/R")
        .positive();
    b.real(cells(&TissueSetup::shear_strength_ratio), "shear_strength_ratio", "1",
           "f_t^0/|f_n^0| of eq. (39)")
        .positive();
    b.real(cells(&TissueSetup::friction), "friction", "1", "mu of the contact that replaces a broken link")
        .non_negative();
    b.choice(cells(&TissueSetup::sliding_clamps), "clamps", {{"fixed", false}, {"sliding", true}},
             "cell edges on the bottom and top lines: fixed (glued), or sliding along the "
             "walls (vertical component imposed only; decision spd-tissue-clamps)");
    b.real(pull(&PullSetup::pull_rate), "pull_rate", "1/t_c",
           "top-clamp speed over H0, times t_c = sqrt(m/k_s)")
        .positive();
    b.real(pull(&PullSetup::strain_max), "strain_max", "1", "largest eps_h = ln(H/H0)").positive().below(2.0);
    b.real(pull(&PullSetup::stop_fraction), "stop_fraction", "1",
           "the run stops once no intact path of links joins the clamps and sigma < stop_fraction "
           "sigma_max (0: run to strain_max)")
        .non_negative()
        .below(1.0);
    b.real(pull(&PullSetup::damping), "damping", "2 sqrt(m k_s)", "global viscous damping on free vertices")
        .non_negative();
    b.real(pull(&PullSetup::dt_factor), "dt_factor", "1", "time step over dt_c = sqrt(m/k_max)").positive();
    b.check([](const TissueOptions& options) {
        const TissueSetup& setup = options.tissue;
        if (setup.material.h >= 0.5 * setup.radius)
            throw InputError("h = " + std::to_string(setup.material.h) +
                             ": the cell wall must be thin against the cell; allowed: h < 0.5 R = 0.5 m");
    });
    return b;
}

void run_tissue(const TissueOptions& options, RunContext& context)
{
    const TissueSetup& setup = options.tissue;
    const PullSetup& pulling = options.pulling;
    context.record_seed(setup.seed);

    Tissue tissue = build_tissue(setup);
    const TissueScales sc = tissue_scales(setup);
    const Tessellation& tess = tissue.tessellation;
    const double R = setup.radius, s_depth = setup.material.s, W = tess.width;
    const double sigma_star = sc.F_star / (2 * R * s_depth); // eq. (37)

    write_links(context, tissue, R);
    // Fig. 31: the measured forces at which one link breaks in pure opening (mode I) and in shear under the
    // compression f_n = |f_n^0|/2 (the contact law, which acts between linked cells too, holds an overlap of
    // |f_n^0|/(2 k_n) = 0.48 (r_i + r_j) at the default cohesion; |f_n^0|/k_n would exceed its
    // 0.95 (r_i + r_j)), against eq. (39); increments of 7e-4 of the threshold per step.
    const CohesiveLaw& law0 = tissue.model.link_law();
    const double dt_probe = pulling.dt_factor * tissue.model.critical_time_step();
    const LinkBreak mode_one =
        break_one_link(tissue.model, 0, 0.0, true, 7e-4 * std::abs(law0.f_n0) / law0.k_n, dt_probe);
    const LinkBreak shear = break_one_link(tissue.model, 0, 0.5 * std::abs(law0.f_n0) / law0.k_n, false,
                                           7e-4 * law0.f_t0 / law0.k_t, dt_probe);

    auto progress = context.progress("spd.tissue");
    // ParaView frames at every 20th record (100 frames of the 2000 records by default; --vtk-every N: every
    // N-th record), the time since the pull started as time value: the cells with W/W0 (Fig. 32) and the
    // cohesive links as lines with their forces and broken state, and the contacts (broken links become
    // frictional contacts).
    const auto frame = [&](const Tissue& t, double time) {
        if (!context.vtk() || !context.vtk()->next(20)) return;
        const ShellModel& model = t.model;
        vtk::PolyData cells = shell_particles(model, t.cells);
        std::vector<double> energy;
        for (int c : t.cells)
            energy.push_back(model.elastic_energy(c) / sc.W0);
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
        const double H = clamp_height(t);
        for (auto& part : parts) {
            part.data.field("strain", std::log(H / t.height0));
            part.data.field("force_top", top_clamp_force(t));
            part.data.field("broken_links", model.broken_links());
        }
        context.vtk()->write(time, parts);
    };
    const PullResult r = pull(
        tissue, pulling, [&](double f) { progress.update(f); }, context.checkpoints(), frame);
    progress.finish();
    context.count_steps(r.steps);

    const CurveMeasures m = curve_measures(r.records, W * s_depth);
    if (!(m.sigma_max > 0))
        throw NumericalError("tissue stress", r.steps, "the top clamp never pulled: sigma_max = 0");
    auto& curve = context.table(
        "tissue.dat",
        {{"eps_h", "1", "vertical strain ln(H/H0), H between the clamped vertex lines"},
         {"sigma_over_sigmamax", "1", "top-clamp stress F_top/(W s) over its maximum (Fig. 33)"},
         {"sigma_over_sigmastar", "1", "top-clamp stress over sigma* = F*/(2Rs), eq. (37)"},
         {"sigma_bottom_over_sigmamax", "1", "bottom-clamp stress over the top maximum"},
         {"broken_links", "1", "links broken so far"},
         {"kinetic_over_W0", "1", "kinetic energy over W0 = (f_n^0)^2/(2 k_n)"}});
    for (std::size_t k = 0; k < r.records.size(); ++k) {
        const TissueRecord& rec = r.records[k];
        curve.row({rec.strain, m.sigma[k] / m.sigma_max, m.sigma[k] / sigma_star,
                   rec.force_bottom / (W * s_depth) / m.sigma_max, double(rec.broken),
                   rec.kinetic_energy / sc.W0});
    }
    const double eps_peak = r.records[m.peak].strain;
    write_snapshots(context, r, eps_peak, R, sc.W0);
    const double crack_height = write_crack(context, tissue, R);
    const CohesiveLaw& law = tissue.model.link_law();
    const double zeta_max = write_yield_curve(context, law);

    const double cell_area = total_cell_area(tess);
    const Cohesion end = cohesion(tissue);
    const int links = static_cast<int>(tissue.model.links().size());
    auto& s = context.summary();
    s["yield_curve_zeta_max"] = zeta_max;
    // Fig. 31, one link broken through the model: f_n at a pure-opening break over f_n^0 (eq. (39): 1), and
    // |f_t| at a shear break in compression over eq. (39)'s threshold f_t^0 sqrt(1 + f_n/|f_n^0|) (1), with
    // the displacements that broke them over those of the law (f_n^0/k_n, sqrt(1.5) f_t^0/k_t).
    // A probe that never broke its link is a failed measurement: NaN, written "nan" (not null).
    s["mode_one_break_fn_over_fn0"] = mode_one.f_n / law.f_n0;
    s["mode_one_break_ft_over_ft0"] = mode_one.f_t / law.f_t0;
    s["mode_one_break_opening_over_law"] = mode_one.moved * law.k_n / std::abs(law.f_n0);
    s["shear_break_fn_over_abs_fn0"] = shear.f_n / std::abs(law.f_n0);
    s["shear_break_ft_over_threshold"] =
        std::abs(shear.f_t) / (law.f_t0 * std::sqrt(1 + shear.f_n / std::abs(law.f_n0)));
    s["shear_break_slip_over_law"] = shear.moved * law.k_t / (std::sqrt(1.5) * law.f_t0);
    s["stress_max"] = m.sigma_max / sigma_star;
    s["strain_at_peak"] = eps_peak;
    s["strain_at_failure"] = finite_or_null(m.strain_at_failure);
    s["failure_width_over_peak_strain"] = finite_or_null((m.strain_at_failure - eps_peak) / eps_peak);
    s["strain_end"] = r.records.back().strain;
    s["broken_links"] = tissue.model.broken_links();
    s["links"] = links;
    s["broken_fraction"] = static_cast<double>(tissue.model.broken_links()) / links;
    s["broken_links_at_peak"] = r.records[m.peak].broken;
    s["separated"] = !end.bottom_to_top;
    s["crack_height_over_H"] = finite_or_null(crack_height);
    s["cell_groups"] = end.groups;
    s["cracks_crossing"] = end.bottom_to_top ? 0 : end.groups - 1;
    s["stress_drops"] = m.drops.size();
    s["largest_stress_drop"] = m.drops.empty() ? 0.0 : *std::max_element(m.drops.begin(), m.drops.end());
    s["stress_drop_growth"] = finite_or_null(m.growth);
    const TissueRecord& at_peak = r.records[m.peak];
    s["force_mismatch_at_peak"] = std::abs(at_peak.force_top - at_peak.force_bottom) / at_peak.force_top;
    s["cells"] = tissue.cells.size();
    s["vertices"] = tissue.model.vertices();
    s["interfaces"] = tissue.interfaces;
    s["tessellation_area_error"] = std::abs(tess.voronoi_area - W * tess.height) / (W * tess.height);
    s["cell_area_error"] = std::abs(cell_area - W * tess.height) / (W * tess.height);
    s["merged_corners"] = tess.merged_corners;
    s["W_over_R"] = W / R;
    s["H0_over_R"] = tissue.height0 / R;
    s["sigma_star"] = sigma_star;
    s["W0"] = sc.W0;
    s["F_star"] = sc.F_star;
    s["dt"] = r.dt;
    s["pull_speed_m_per_s"] = r.speed;
}
} // namespace

void register_spd_tissue_scenes(SceneRegistry& registry)
{
    Scene tissue =
        bound_scene("spd.tissue",
                    "SPD section 6: tensile fracture of a tissue of Laguerre-Voronoi cells joined by "
                    "cohesive links (eq. 39); sigma/sigma_max vs eps_h, broken links, W/W0 snapshots "
                    "(Figs. 30-34)",
                    tissue_binding(), run_tissue);
    tissue.checkpoints = true;
    registry.add(std::move(tissue)
                     .needing([](const Parameters& p) {
                         // A cell of a planar tiling has 6 edges on average (Euler's formula).
                         return spd::shell_model_memory(double(p.integer("rows")) *
                                                            double(p.integer("columns")) * 6.0 *
                                                            double(p.integer("edge_segments")),
                                                        "vertices (rows x columns x 6 x edge_segments)");
                     })
                     .with_vtk());
}

} // namespace softgrain
