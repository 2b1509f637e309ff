// dpm.shear_friction: the simple-shear test of section 9.3.3 (Figs. 9.8, 9.9): mu_eff against x/D.
#include "dpm/protocols/shear_friction.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/preferred_shape.hpp"
#include "dpm/protocols/frozen_contact.hpp"
#include "dpm/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace softgrain::dpm {

namespace {

enum class FrameRange { contact, scan };

// Appendix A's scan freezes the shapes of a smooth contact at the maximum of mu_eff.
const char* const frozen_scan_needs =
    "frozen_scan = true needs interaction = smooth and a contact (Appendix A)";

// dpm.shear_friction's options: the shear test, the frames drawn, and the frozen-contact scan.
struct ShearFrictionOptions
{
    ShearTestOptions test;
    FrameRange frame_range = FrameRange::contact;
    int frames = 7;
    bool frozen_scan = false;
    int scan_points = 41; // per direction
};

// The scan goes from x_start to x_end in steps dx, counted by an int: an empty or reversed range, or a count
// beyond the counter (x_start = 1e308 made it 1e310, and the reservation of its configurations threw), is
// refused before the run, naming the keys.
void check_scan_range(const ShearTestOptions& test)
{
    if (!(test.x_end >= test.x_start))
        throw InputError("'x_end' = " + number_text(test.x_end) + " is below 'x_start' = " +
                         number_text(test.x_start) + "; allowed: x_end >= x_start (the scan moves mu in +x)");
    const double steps = std::floor((test.x_end - test.x_start) / test.dx + 1e-9);
    constexpr double max_steps = std::numeric_limits<int>::max() - 1;
    if (!(steps <= max_steps))
        throw InputError("'x_start' = " + number_text(test.x_start) +
                         " to 'x_end' = " + number_text(test.x_end) +
                         " in steps 'dx' = " + number_text(test.dx) + " is " + number_text(steps) +
                         " steps; allowed: at most " + number_text(max_steps) + " steps");
}

OptionBinding<ShearFrictionOptions> shear_friction_binding()
{
    const auto test = [](auto field) { return path(&ShearFrictionOptions::test, field); };
    OptionBinding<ShearFrictionOptions> binding;
    binding.choice(test(&ShearTestOptions::interaction), "interaction",
                   {{"rough", InteractionKind::rough}, {"smooth", InteractionKind::smooth}},
                   "rough (eqs. 9.3-9.4) or smooth (9.5-9.9)");
    binding
        .integer(test(&ShearTestOptions::nodes), "nodes", "1",
                 "vertices N per particle (even: flat bottom and top)")
        .at_least(4);
    binding
        .real(test(&ShearTestOptions::C), "C", "1", "C = R/sigma, polygon circumradius over vertex diameter")
        .positive();
    binding
        .real_or_keyword(test(&ShearTestOptions::A0), "A0", "min", "1",
                         "preferred shape parameter (N l0)^2/(4 pi a0); min = N tan(pi/N)/pi")
        .at_least(1.0);
    binding
        .real(test(&ShearTestOptions::kl), "kl", "k_c", "edge stiffness k_l/k_c (stiff shells 100, floppy 1)")
        .positive();
    binding
        .real(test(&ShearTestOptions::kb), "kb", "k_c sigma^2",
              "bending stiffness k_b/(k_c sigma^2); 0 = floppy")
        .non_negative();
    binding
        .real(test(&ShearTestOptions::ka), "ka", "k_c sigma^2/a0^2", "area stiffness k_a a0^2/(k_c sigma^2)")
        .positive();
    binding
        .real(test(&ShearTestOptions::k_constraint), "k_constraint", "k_c", "anchor springs k_constraint/k_c")
        .positive();
    binding
        .real(test(&ShearTestOptions::overlap), "overlap", "sigma",
              "rest overlap 1 - r/sigma of the groove contact (sets the gap)")
        .non_negative()
        .below(1.0);
    binding.real(test(&ShearTestOptions::dx), "dx", "D_beta", "shift of the anchors per step").positive();
    binding.real(test(&ShearTestOptions::x_start), "x_start", "D_beta", "first x_bm / D_beta");
    binding.real(test(&ShearTestOptions::x_end), "x_end", "D_beta", "last x_bm / D_beta");
    binding.seed(test(&ShearTestOptions::seed), "seed", "noise seed for floppy particles (kb = 0)");
    binding.choice(&ShearFrictionOptions::frame_range, "frame_range",
                   {{"contact", FrameRange::contact}, {"scan", FrameRange::scan}},
                   "frames evenly spaced from the first to the last contact, or over the whole scan "
                   "x_start..x_end (for particles that may not touch)");
    binding
        .integer(&ShearFrictionOptions::frames, "frames", "1",
                 "snapshots over frame_range written to frames.dat")
        .non_negative();
    binding.boolean(&ShearFrictionOptions::frozen_scan, "frozen_scan",
                    "Appendix A (Fig. 9.19e): mu_eff with the shapes of the maximum frozen, mu "
                    "translated (smooth interaction)");
    binding
        .integer(&ShearFrictionOptions::scan_points, "scan_points", "1", "frozen scan: points per direction")
        .at_least(3);
    binding.check([](const ShearFrictionOptions& options) {
        preferred_shape_parameter(options.test.A0, options.test.nodes); // A0 >= A_min(nodes), or min
        if (options.frozen_scan && options.test.interaction != InteractionKind::smooth)
            throw InputError(frozen_scan_needs);
        check_scan_range(options.test);
    });
    return binding;
}

std::vector<Column> outline_columns()
{
    return {{"frame", "1", "snapshot number (1, 2, ...; 0 = final state)"},
            {"x_over_D", "1", "x_bm / D_beta of the snapshot"},
            {"particle", "1", "0 = beta (fixed), 1 = mu (dragged)"},
            {"x", "sigma", "vertex x (closed outline: first vertex repeated)"},
            {"y", "sigma", "vertex y"}};
}

void write_outlines(Table& table, const DpmSystem& system, const Eigen::VectorXd& x, int frame,
                    double x_over_d)
{
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle& particle = system.particles[m];
        for (int v = 0; v <= particle.count; ++v) { // closed outline
            const int vertex = particle.first + v % particle.count;
            table.row({double(frame), x_over_d, double(m), x(2 * vertex), x(2 * vertex + 1)});
        }
    }
}

// Frames 1..n of Figs. 9.8(a-c), 9.9(a, c): the relaxed configurations nearest to n positions evenly spaced
// from the first to the last contact (frame_range = contact) or over the whole scan (frame_range = scan, for
// particles that may not touch; decision dpm-shear-frames).
void write_frames(const ShearFrictionOptions& options, const ShearTestResult& test, RunContext& context)
{
    const int frames = options.frames;
    const bool over_contact = options.frame_range == FrameRange::contact;
    if (frames == 0 || (over_contact ? test.samples.empty() : test.configurations.empty())) return;
    auto& table = context.table("frames.dat", outline_columns());
    const double first = over_contact ? test.samples.front().x_over_d : test.configurations.front().first;
    const double last = over_contact ? test.samples.back().x_over_d : test.configurations.back().first;
    for (int k = 0; k < frames; ++k) {
        const double wanted = frames == 1 ? first : first + (last - first) * k / (frames - 1);
        const auto nearest = std::min_element(
            test.configurations.begin(), test.configurations.end(), [wanted](const auto& a, const auto& b) {
                return std::abs(a.first - wanted) < std::abs(b.first - wanted);
            });
        write_outlines(table, test.system, nearest->second, k + 1, nearest->first);
    }
}

// The anchors' rest positions (the constraint springs that hold beta and drag mu, section 9.3.3) as vertex
// cells, with the anchored vertex as cell data `vertex`.
vtk::PolyData anchor_points(const DpmSystem& system)
{
    vtk::PolyData data;
    std::vector<std::int64_t> vertices;
    for (const Anchor& anchor : system.anchors) {
        data.add_vertex(data.add_point(anchor.position));
        vertices.push_back(anchor.vertex);
    }
    data.cell_ids("vertex", std::move(vertices));
    return data;
}

// ParaView frames, one per shear step (--vtk-every N: every N-th), x_bm / D_beta as the time value: the two
// particles, their contact, the anchors and the shear path (mu's centre, its vertex mean, at every step so
// far, as one polyline with x_over_D per point). Field data: x_over_D, F_n, F_t [k_c sigma] and mu_eff (NaN
// out of contact).
class ShearFrames
{
  public:
    explicit ShearFrames(vtk::Series& series) : series_(series) {}
    void operator()(const DpmSystem& system, const Eigen::VectorXd& x, const ShearSample& sample)
    {
        const Particle& mu = system.particles[1];
        path_.push_back(x.segment(2 * mu.first, 2 * mu.count).reshaped(2, mu.count).rowwise().mean());
        path_x_over_d_.push_back(sample.x_over_d);
        if (!series_.next()) return;
        vtk::PolyData path;
        std::vector<std::int64_t> line;
        for (const Eigen::Vector2d& centre : path_)
            line.push_back(path.add_point(centre));
        path.add_line(line);
        path.point_scalars("x_over_D", path_x_over_d_);
        std::vector<vtk::Part> parts{{"particles", dpm_particles(system, x)},
                                     {"contacts", dpm_contacts(system, x)},
                                     {"anchors", anchor_points(system)},
                                     {"path", std::move(path)}};
        for (auto& part : parts) {
            part.data.field("x_over_D", sample.x_over_d);
            part.data.field("F_n", sample.normal_force);
            part.data.field("F_t", sample.tangential_force);
            part.data.field("mu_eff", sample.normal_force > 0 ? sample.mu_eff : NAN);
        }
        series_.write(sample.x_over_d, parts);
    }

  private:
    vtk::Series& series_;
    std::vector<Eigen::Vector2d> path_;
    std::vector<double> path_x_over_d_;
};

// The shear test and, with frozen_scan, Appendix A's scan of the frozen contact at the maximum of mu_eff.
struct ShearFrictionResult
{
    ShearTestResult test;
    std::optional<FrozenContactScan> frozen;
};

ShearFrictionResult shear_friction(const ShearFrictionOptions& options, RunContext& context)
{
    ShearFrictionResult result;
    result.test = context.vtk() ? simple_shear_test(options.test, ShearFrames(*context.vtk()))
                                : simple_shear_test(options.test);
    if (options.frozen_scan) {
        if (result.test.samples.empty()) throw InputError(frozen_scan_needs);
        result.frozen = frozen_contact_scan(result.test.system, result.test.x_star, options.scan_points,
                                            options.scan_points);
    }
    return result;
}

void write_frozen_scan(const FrozenContactScan& scan, const ShearTestResult& test, RunContext& context)
{
    auto& table = context.table(
        "frozen_contact.dat",
        {{"rx", "sigma", "x of r_{beta r, mu t} (mu translated rigidly, shapes of the maximum)"},
         {"ry", "sigma", "y of r_{beta r, mu t}"},
         {"overlap_fraction", "1", "ry / ry at zero overlap (0 = deepest, 1 = zero-overlap limit)"},
         {"mu_eff", "1", "F_t / F_n, eq. (9.10)"},
         {"F_n", "k_c sigma", "eq. (9.11)"},
         {"F_t", "k_c sigma", "eq. (9.12)"}});
    for (const FrozenContactPoint& point : scan.points)
        table.row({point.rx, point.ry, point.overlap_fraction, point.mu_eff, point.normal, point.tangential});
    write_outlines(context.table("star_shape.dat", outline_columns()), test.system, test.x_star, 0,
                   test.x_at_max);
    auto& summary = context.summary();
    summary["frozen_star_rx"] = scan.star.x();
    summary["frozen_star_ry"] = scan.star.y();
    summary["frozen_mu_eff_star"] = scan.mu_eff_star;
    summary["frozen_mu_eff_max_at_star_height"] = scan.mu_eff_max_at_star_height;
    summary["frozen_rx_at_max"] = scan.rx_at_max;
    summary["frozen_min_force"] = scan.min_force;
    summary["frozen_mu_eff_zero_overlap"] = scan.mu_eff_zero_overlap;
}

void report_shear_friction(const ShearFrictionOptions& options, const ShearFrictionResult& result,
                           RunContext& context)
{
    const ShearTestResult& test = result.test;
    auto& table = context.table("shear.dat", {{"x_over_D", "1", "x_bm / D_beta (section 9.3.3)"},
                                              {"mu_eff", "1", "F_t / F_n, eq. (9.10)"},
                                              {"F_n", "k_c sigma", "normal force on mu, eq. (9.11)"},
                                              {"F_t", "k_c sigma", "tangential force on mu, eq. (9.12)"},
                                              {"energy", "k_c sigma^2", "total energy after relaxation"}});
    for (const ShearSample& sample : test.samples)
        table.row(
            {sample.x_over_d, sample.mu_eff, sample.normal_force, sample.tangential_force, sample.energy});
    write_outlines(context.table("final_shape.dat", outline_columns()), test.system, test.x, 0, 0);
    write_frames(options, test, context);
    if (result.frozen) write_frozen_scan(*result.frozen, test, context);

    auto& summary = context.summary();
    summary["mu_eff_max"] = test.mu_eff_max;
    summary["x_at_max"] = test.x_at_max;
    summary["mu_eff_max_eq_9_13"] = rough_friction_maximum(options.test.C, options.test.nodes);
    summary["contact_samples"] = test.samples.size();
    summary["D_beta"] = test.d_beta;
}

void run_shear_friction(const ShearFrictionOptions& options, RunContext& context)
{
    if (options.test.kb == 0) context.record_seed(options.test.seed);
    const ShearFrictionResult result = shear_friction(options, context);
    context.count_steps(result.test.iterations);
    report_shear_friction(options, result, context);
}

} // namespace

Scene shear_friction_scene()
{
    return bound_scene("dpm.shear_friction",
                       "DPM sec. 9.3.3: simple shear of two rough or smooth particles, mu_eff against x/D "
                       "(Figs. 9.8, 9.9), maximum against eq. (9.13)",
                       shear_friction_binding(), run_shear_friction)
        .needing(shear_friction_binding().estimate([](const ShearFrictionOptions& options) {
            return dpm_vertex_memory(2.0 * options.test.nodes, "vertices (2 x nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
