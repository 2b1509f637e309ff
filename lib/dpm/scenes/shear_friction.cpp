// dpm.shear_friction: the simple-shear test of section 9.3.3 (Figs. 9.8, 9.9): mu_eff against x/D.
#include "dpm/shear_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/frozen_contact.hpp"
#include "dpm/preferred_shape.hpp"
#include "dpm/shear_friction.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::dpm {

namespace {

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
        const Particle& q = system.particles[m];
        for (int v = 0; v <= q.count; ++v) { // closed outline
            const int w = q.first + v % q.count;
            table.row({double(frame), x_over_d, double(m), x(2 * w), x(2 * w + 1)});
        }
    }
}

// Frames 1..n of Figs. 9.8(a-c), 9.9(a, c): the relaxed configurations nearest to n positions evenly spaced
// from the first to the last contact (frame_range = contact) or over the whole scan (frame_range = scan, for
// particles that may not touch; decision dpm-shear-frames).
void write_frames(const Parameters& p, const ShearTestResult& r, RunContext& context)
{
    const int frames = static_cast<int>(p.integer("frames"));
    const bool over_contact = p.choice("frame_range") == "contact";
    if (frames == 0 || (over_contact ? r.samples.empty() : r.configurations.empty())) return;
    auto& table = context.table("frames.dat", outline_columns());
    const double first = over_contact ? r.samples.front().x_over_d : r.configurations.front().first;
    const double last = over_contact ? r.samples.back().x_over_d : r.configurations.back().first;
    for (int k = 0; k < frames; ++k) {
        const double wanted = frames == 1 ? first : first + (last - first) * k / (frames - 1);
        const auto nearest = std::min_element(
            r.configurations.begin(), r.configurations.end(), [wanted](const auto& a, const auto& b) {
                return std::abs(a.first - wanted) < std::abs(b.first - wanted);
            });
        write_outlines(table, r.system, nearest->second, k + 1, nearest->first);
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

} // namespace

void run_shear_friction(const Parameters& p, RunContext& context)
{
    ShearTestOptions o;
    o.interaction = interaction_from_name(p.choice("interaction"));
    o.nodes = static_cast<int>(p.integer("nodes"));
    o.C = p.real("C");
    o.A0 = preferred_shape_parameter(p, "A0", o.nodes);
    o.kl = p.real("kl");
    o.kb = p.real("kb");
    o.ka = p.real("ka");
    o.k_constraint = p.real("k_constraint");
    o.overlap = p.real("overlap");
    o.dx = p.real("dx");
    o.x_start = p.real("x_start");
    o.x_end = p.real("x_end");
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    if (o.kb == 0) context.record_seed(o.seed);
    const ShearTestResult r =
        context.vtk() ? simple_shear_test(o, ShearFrames(*context.vtk())) : simple_shear_test(o);
    context.count_steps(r.iterations);

    auto& table = context.table("shear.dat", {{"x_over_D", "1", "x_bm / D_beta (section 9.3.3)"},
                                              {"mu_eff", "1", "F_t / F_n, eq. (9.10)"},
                                              {"F_n", "k_c sigma", "normal force on mu, eq. (9.11)"},
                                              {"F_t", "k_c sigma", "tangential force on mu, eq. (9.12)"},
                                              {"energy", "k_c sigma^2", "total energy after relaxation"}});
    for (const ShearSample& s : r.samples)
        table.row({s.x_over_d, s.mu_eff, s.normal_force, s.tangential_force, s.energy});
    write_outlines(context.table("final_shape.dat", outline_columns()), r.system, r.x, 0, 0);
    write_frames(p, r, context);

    auto& s = context.summary();
    if (p.boolean("frozen_scan")) {
        if (r.samples.empty() || o.interaction != InteractionKind::smooth)
            throw InputError("frozen_scan = true needs interaction = smooth and a contact (Appendix A)");
        const int nx = static_cast<int>(p.integer("scan_points"));
        const FrozenContactScan scan = frozen_contact_scan(r.system, r.x_star, nx, nx);
        auto& scan_table = context.table(
            "frozen_contact.dat",
            {{"rx", "sigma", "x of r_{beta r, mu t} (mu translated rigidly, shapes of the maximum)"},
             {"ry", "sigma", "y of r_{beta r, mu t}"},
             {"overlap_fraction", "1", "ry / ry at zero overlap (0 = deepest, 1 = zero-overlap limit)"},
             {"mu_eff", "1", "F_t / F_n, eq. (9.10)"},
             {"F_n", "k_c sigma", "eq. (9.11)"},
             {"F_t", "k_c sigma", "eq. (9.12)"}});
        for (const FrozenContactPoint& q : scan.points)
            scan_table.row({q.rx, q.ry, q.overlap_fraction, q.mu_eff, q.normal, q.tangential});
        write_outlines(context.table("star_shape.dat", outline_columns()), r.system, r.x_star, 0, r.x_at_max);
        s["frozen_star_rx"] = scan.star.x();
        s["frozen_star_ry"] = scan.star.y();
        s["frozen_mu_eff_star"] = scan.mu_eff_star;
        s["frozen_mu_eff_max_at_star_height"] = scan.mu_eff_max_at_star_height;
        s["frozen_rx_at_max"] = scan.rx_at_max;
        s["frozen_min_force"] = scan.min_force;
        s["frozen_mu_eff_zero_overlap"] = scan.mu_eff_zero_overlap;
    }

    s["mu_eff_max"] = r.mu_eff_max;
    s["x_at_max"] = r.x_at_max;
    s["mu_eff_max_eq_9_13"] = rough_friction_maximum(o.C, o.nodes);
    s["contact_samples"] = r.samples.size();
    s["D_beta"] = r.d_beta;
}

std::vector<ParameterSpec> shear_friction_parameters()
{
    return {
        ParameterSpec::choice("interaction", "rough", {"rough", "smooth"},
                              "rough (eqs. 9.3-9.4) or smooth (9.5-9.9)"),
        ParameterSpec::integer("nodes", 8, "1", "vertices N per particle (even: flat bottom and top)")
            .at_least(4),
        ParameterSpec::real("C", 1.3, "1", "C = R/sigma, polygon circumradius over vertex diameter")
            .positive(),
        preferred_shape_parameter_spec(1.0, true,
                                       "preferred shape parameter (N l0)^2/(4 pi a0); min = N tan(pi/N)/pi"),
        ParameterSpec::real("kl", 100.0, "k_c", "edge stiffness k_l/k_c (stiff shells 100, floppy 1)")
            .positive(),
        ParameterSpec::real("kb", 171.0, "k_c sigma^2", "bending stiffness k_b/(k_c sigma^2); 0 = floppy")
            .non_negative(),
        ParameterSpec::real("ka", 14.0, "k_c sigma^2/a0^2", "area stiffness k_a a0^2/(k_c sigma^2)")
            .positive(),
        ParameterSpec::real("k_constraint", 100.0, "k_c", "anchor springs k_constraint/k_c").positive(),
        ParameterSpec::real("overlap", 0.01, "sigma",
                            "rest overlap 1 - r/sigma of the groove contact (sets the gap)")
            .non_negative()
            .below(1.0),
        ParameterSpec::real("dx", 0.016, "D_beta", "shift of the anchors per step").positive(),
        ParameterSpec::real("x_start", -0.7, "D_beta", "first x_bm / D_beta"),
        ParameterSpec::real("x_end", 0.7, "D_beta", "last x_bm / D_beta"),
        ParameterSpec::seed("seed", 1, "noise seed for floppy particles (kb = 0)"),
        ParameterSpec::choice(
            "frame_range", "contact", {"contact", "scan"},
            "frames evenly spaced from the first to the last contact, or over the whole scan "
            "x_start..x_end (for particles that may not touch)"),
        ParameterSpec::integer("frames", 7, "1", "snapshots over frame_range written to frames.dat")
            .non_negative(),
        ParameterSpec::boolean("frozen_scan", false,
                               "Appendix A (Fig. 9.19e): mu_eff with the shapes of the maximum frozen, mu "
                               "translated (smooth interaction)"),
        ParameterSpec::integer("scan_points", 41, "1", "frozen scan: points per direction").at_least(3),
    };
}

} // namespace softgrain::dpm
