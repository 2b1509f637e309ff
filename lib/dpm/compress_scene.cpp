// dpm.compress2d: a 2D elastic shell or spring-network disk squeezed between two plates (section 9.3.4,
// Fig. 9.10): F~ against delta~ = delta/D, eq. (9.14) for the cylinder at the same forces, small-strain
// exponents.
#include "dpm/compress_scene.hpp"

#include "core/fits.hpp"
#include "core/output.hpp"
#include "dpm/compress.hpp"
#include "dpm/spring_network.hpp"
#include "dpm/vtk_frames.hpp"

#include <cmath>

namespace softgrain::dpm {

void run_compress2d(const Parameters& p, RunContext& context)
{
    CompressionOptions o;
    o.nodes = static_cast<int>(p.integer("nodes"));
    o.kl = p.real("kl");
    o.kb = p.real("kb");
    o.ka = p.real("ka");
    o.network_nodes = static_cast<int>(p.integer("network_nodes"));
    o.network_jitter = p.real("jitter");
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    o.steps = static_cast<int>(p.integer("steps"));
    o.delta_min = p.real("delta_min");
    o.delta_max = p.real("delta_max");
    const bool network = p.choice("model") == "spring_network";
    if (network) context.record_seed(o.seed);
    // ParaView frames, one per compression step, delta/D as the time value: the body (the shell as a
    // polygon, the network as its nodes (vertex cells) and springs (lines)) and the plates.
    Eigen::VectorXd shell_x;
    const DpmSystem shell = compression_shell(o, shell_x);
    const SpringNetwork net =
        network && context.vtk()
            ? disordered_triangular_disk(o.network_nodes, o.network_jitter, o.network_k, o.seed)
            : SpringNetwork{};
    const auto frame = [&](const Eigen::VectorXd& x, double top, const CompressionSample& sample) {
        if (!context.vtk() || !context.vtk()->next()) return;
        vtk::PolyData body = network ? spring_network_body(net, x) : dpm_particles(shell, x);
        double x_min = INFINITY, x_max = -INFINITY;
        for (Eigen::Index v = 0; v < x.size() / 2; ++v)
            x_min = std::min(x_min, x(2 * v)), x_max = std::max(x_max, x(2 * v));
        std::vector<vtk::Part> parts{{"particles", std::move(body)},
                                     {"plates", plates(x_min - 1, x_max + 1, 0.0, top)}};
        for (auto& part : parts) {
            part.data.field("delta_over_D", sample.delta_over_d);
            part.data.field("force", sample.force);
        }
        context.vtk()->write(sample.delta_over_d, parts);
    };
    const CompressionResult r = network ? compress_spring_network(o, frame) : compress_shell(o, frame);
    context.count_steps(r.iterations);
    // Moduli for F~ (decision dpm-compress-moduli): the ordered triangular lattice for the network; for the
    // shell, E = k_l (stretching modulus k_l l0 over a wall thickness sigma = l0) and nu = 0.
    const double E = network ? triangular_lattice_young_modulus(o.network_k) : o.kl;
    const double nu = network ? triangular_lattice_poisson_ratio : 0.0;
    const double d_tilde = p.real("D_tilde");

    auto& table = context.table(
        "force.dat",
        {{"delta", "D", "compression delta / D"},
         {"F", "k_c sigma", "force F_a on the top plate"},
         {"F_over_D", "k_c", "F_a / D"},
         {"F_tilde", "1", "F~ = F_a (1 - nu^2)/(E D D~) (2D: force per length over E D, times 1/D~)"},
         {"delta_eq_9_14", "1", "delta~ of eq. (9.14) for the cylinder at this F~ and D~"}});
    std::vector<double> fit_delta, fit_force, fit_delta_cylinder;
    for (const CompressionSample& s : r.samples) {
        const double f_tilde = s.force * (1 - nu * nu) / (E * r.diameter * d_tilde);
        const double cylinder = s.force > 0 ? cylinder_compression(f_tilde, d_tilde) : 0.0;
        table.row({s.delta_over_d, s.force, s.force / r.diameter, f_tilde, cylinder});
        if (s.delta_over_d <= p.real("fit_max") && s.force > 0) {
            fit_delta.push_back(s.delta_over_d);
            fit_force.push_back(s.force);
            fit_delta_cylinder.push_back(cylinder);
        }
    }
    auto& s = context.summary();
    s["diameter"] = r.diameter;
    s["E"] = E;
    s["nu"] = nu;
    s["small_strain_exponent"] =
        value_or_null(fit_power_law_exponent(fit_delta, fit_force, minimum_exponent_points));
    // The exponent of eq. (9.14) over the same forces: its local slope 1 + 1/(1 + ln(pi/(D~^3 F~))) > 1.
    s["eq_9_14_exponent"] =
        value_or_null(fit_power_law_exponent(fit_delta_cylinder, fit_force, minimum_exponent_points));
    if (network) {
        s["network_nodes"] = o.network_nodes;
        s["network_springs"] = r.springs;
        s["coordination"] = 2.0 * r.springs / o.network_nodes;
    }
}

std::vector<ParameterSpec> compress2d_parameters()
{
    return {
        ParameterSpec::choice("model", "shell", {"shell", "spring_network"},
                              "elastic shell (Fig. 9.10b) or spring-network disk (Fig. 9.10a)"),
        ParameterSpec::integer("nodes", 100, "1", "shell: vertices N_mu (paper: 100)").at_least(8),
        ParameterSpec::real("kl", 1.0, "k_c", "shell: edge stiffness k_l/k_c").positive(),
        ParameterSpec::real("kb", 1.0, "k_c sigma^2", "shell: bending stiffness k_b/(k_c sigma^2)")
            .positive(),
        ParameterSpec::real("ka", 1.0, "k_c sigma^2/a0^2", "shell: area stiffness k_a a0^2/(k_c sigma^2)")
            .positive(),
        ParameterSpec::integer("network_nodes", 1100, "1", "network: nodes (paper: 1100, 3197 springs)")
            .at_least(7),
        ParameterSpec::real("jitter", 0.2, "lattice spacing",
                            "network: random node displacement (disorder) of the triangular lattice")
            .non_negative()
            .below(0.5),
        ParameterSpec::seed("seed", 1, "network: seed of the node displacements"),
        ParameterSpec::integer("steps", 30, "1", "compression steps, log-spaced").at_least(3),
        ParameterSpec::real("delta_min", 1e-4, "D", "smallest compression delta/D").positive(),
        ParameterSpec::real("delta_max", 0.2, "D", "largest compression delta/D").positive().below(1.0),
        ParameterSpec::real("fit_max", 1e-2, "D", "small-strain exponents fitted for delta/D up to this")
            .positive(),
        ParameterSpec::real("D_tilde", 1.0, "1", "D~ = D/l, cylinder diameter over length in eq. (9.14)")
            .positive(),
    };
}

} // namespace softgrain::dpm
