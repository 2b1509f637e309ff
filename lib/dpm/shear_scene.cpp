// dpm.shear_friction: the simple-shear test of section 9.3.3 (Figs. 9.8, 9.9): mu_eff against x/D.
#include "dpm/shear_scene.hpp"

#include "core/output.hpp"
#include "dpm/preferred_shape.hpp"
#include "dpm/shear_friction.hpp"

namespace softgrain::dpm {

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
    const ShearTestResult r = simple_shear_test(o);
    context.count_steps(r.iterations);

    auto& table = context.table("shear.dat", {{"x_over_D", "1", "x_bm / D_beta (section 9.3.3)"},
                                              {"mu_eff", "1", "F_t / F_n, eq. (9.10)"},
                                              {"F_n", "k_c sigma", "normal force on mu, eq. (9.11)"},
                                              {"F_t", "k_c sigma", "tangential force on mu, eq. (9.12)"},
                                              {"energy", "k_c sigma^2", "total energy after relaxation"}});
    for (const ShearSample& s : r.samples)
        table.row({s.x_over_d, s.mu_eff, s.normal_force, s.tangential_force, s.energy});
    auto& shape = context.table("final_shape.dat", {{"particle", "1", "0 = beta (fixed), 1 = mu (dragged)"},
                                                    {"x", "sigma", "vertex x"},
                                                    {"y", "sigma", "vertex y"}});
    for (std::size_t m = 0; m < r.system.particles.size(); ++m) {
        const Particle& q = r.system.particles[m];
        for (int v = 0; v <= q.count; ++v) { // closed outline
            const int w = q.first + v % q.count;
            shape.row({double(m), r.x(2 * w), r.x(2 * w + 1)});
        }
    }

    auto& s = context.summary();
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
        ParameterSpec::integer("seed", 1, "1", "noise seed for floppy particles (kb = 0)").non_negative(),
    };
}

} // namespace softgrain::dpm
