// dpm.compress2d: a 2D elastic shell squeezed between two plates (section 9.3.4, Fig. 9.10): F_a against
// delta/D and its small-strain exponent.
#include "dpm/compress_scene.hpp"

#include "core/output.hpp"
#include "dpm/compress.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>

namespace softgrain::dpm {

void run_compress2d(const Parameters& p, RunContext& context)
{
    CompressionOptions o;
    o.nodes = static_cast<int>(p.integer("nodes"));
    o.kl = p.real("kl");
    o.kb = p.real("kb");
    o.ka = p.real("ka");
    o.steps = static_cast<int>(p.integer("steps"));
    o.delta_max = p.real("delta_max");
    const CompressionResult r = compress_shell(o);
    context.count_steps(r.iterations);
    auto& table =
        context.table("force.dat", {{"delta", "D", "compression delta / D"},
                                    {"F", "k_c sigma", "force F_a on the top plate"},
                                    {"F_over_D", "k_c", "F_a / D (the shell has no E, nu for F~)"}});
    std::vector<double> log_delta, log_force;
    for (const CompressionSample& s : r.samples) {
        table.row({s.delta_over_d, s.force, s.force / r.diameter});
        if (s.delta_over_d <= p.real("fit_max") && s.force > 0) {
            log_delta.push_back(std::log(s.delta_over_d));
            log_force.push_back(std::log(s.force));
        }
    }
    auto& s = context.summary();
    s["diameter"] = r.diameter;
    if (log_delta.size() >= 3) {
        double c0, c1, c00, c01, c11, sumsq;
        gsl_fit_linear(log_delta.data(), 1, log_force.data(), 1, log_delta.size(), &c0, &c1, &c00, &c01, &c11,
                       &sumsq);
        s["small_strain_exponent"] = c1;
    } else {
        s["small_strain_exponent"] = nullptr;
    }
}

std::vector<ParameterSpec> compress2d_parameters()
{
    return {
        ParameterSpec::choice("model", "shell", {"shell"},
                              "elastic shell of Fig. 9.10(b) (the spring-network disk is not implemented)"),
        ParameterSpec::integer("nodes", 100, "1", "vertices N_mu of the shell (paper: 100)").at_least(8),
        ParameterSpec::real("kl", 1.0, "k_c", "edge stiffness k_l/k_c").positive(),
        ParameterSpec::real("kb", 1.0, "k_c sigma^2", "bending stiffness k_b/(k_c sigma^2)").positive(),
        ParameterSpec::real("ka", 1.0, "k_c sigma^2/a0^2", "area stiffness k_a a0^2/(k_c sigma^2)")
            .positive(),
        ParameterSpec::integer("steps", 30, "1", "compression steps, log-spaced from 1e-4 D").at_least(3),
        ParameterSpec::real("delta_max", 0.2, "D", "largest compression delta/D").positive().below(1.0),
        ParameterSpec::real("fit_max", 1e-2, "D", "small-strain exponent fitted for delta/D up to this")
            .positive(),
    };
}

} // namespace softgrain::dpm
