// dpm.compress2d: a 2D elastic shell or spring-network disk squeezed between two plates (section 9.3.4,
// Fig. 9.10): F~ against delta~ = delta/D, eq. (9.14) for the cylinder at the same forces, small-strain
// exponents.
#include "dpm/scenes/scenes.hpp"

#include "core/fits.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/spring_network.hpp"
#include "dpm/protocols/compress.hpp"

#include <cmath>

namespace softgrain::dpm {

namespace {

enum class Compress2dBody { shell, spring_network };

// dpm.compress2d's options: the compression, the body, and what the report fits and compares.
struct Compress2dOptions
{
    CompressionOptions compression;
    Compress2dBody body = Compress2dBody::shell;
    double fit_max = 1e-2; // small-strain exponents fitted for delta/D up to this
    double D_tilde = 1.0;  // D~ = D/l of eq. (9.14)
};

OptionBinding<Compress2dOptions> compress2d_binding()
{
    const auto compression = [](auto field) { return path(&Compress2dOptions::compression, field); };
    OptionBinding<Compress2dOptions> binding;
    binding.choice(&Compress2dOptions::body, "model",
                   {{"shell", Compress2dBody::shell}, {"spring_network", Compress2dBody::spring_network}},
                   "elastic shell (Fig. 9.10b) or spring-network disk (Fig. 9.10a)");
    binding
        .integer(compression(&CompressionOptions::nodes), "nodes", "1", "shell: vertices N_mu (paper: 100)")
        .at_least(8);
    binding.real(compression(&CompressionOptions::kl), "kl", "k_c", "shell: edge stiffness k_l/k_c")
        .positive();
    binding
        .real(compression(&CompressionOptions::kb), "kb", "k_c sigma^2",
              "shell: bending stiffness k_b/(k_c sigma^2)")
        .positive();
    binding
        .real(compression(&CompressionOptions::ka), "ka", "k_c sigma^2/a0^2",
              "shell: area stiffness k_a a0^2/(k_c sigma^2)")
        .positive();
    binding
        .integer(compression(&CompressionOptions::network_nodes), "network_nodes", "1",
                 "network: nodes (paper: 1100, 3197 springs)")
        .at_least(7);
    binding
        .real(compression(&CompressionOptions::network_jitter), "jitter", "lattice spacing",
              "network: random node displacement (disorder) of the triangular lattice")
        .non_negative()
        .below(0.5);
    binding.seed(compression(&CompressionOptions::seed), "seed", "network: seed of the node displacements");
    binding.integer(compression(&CompressionOptions::steps), "steps", "1", "compression steps, log-spaced")
        .at_least(3);
    binding
        .real(compression(&CompressionOptions::delta_min), "delta_min", "D", "smallest compression delta/D")
        .positive();
    binding.real(compression(&CompressionOptions::delta_max), "delta_max", "D", "largest compression delta/D")
        .positive()
        .below(1.0);
    binding
        .real(&Compress2dOptions::fit_max, "fit_max", "D",
              "small-strain exponents fitted for delta/D up to this")
        .positive();
    binding
        .real(&Compress2dOptions::D_tilde, "D_tilde", "1",
              "D~ = D/l, cylinder diameter over length in eq. (9.14)")
        .positive();
    return binding;
}

void run_compress2d(const Compress2dOptions& options, RunContext& context)
{
    const CompressionOptions& compression = options.compression;
    const bool network = options.body == Compress2dBody::spring_network;
    if (network) context.record_seed(compression.seed);
    // ParaView frames, one per compression step, delta/D as the time value: the body (the shell as a
    // polygon, the network as its nodes (vertex cells) and springs (lines)) and the plates.
    Eigen::VectorXd shell_x;
    const DpmSystem shell = compression_shell(compression, shell_x);
    const SpringNetwork net =
        network && context.vtk()
            ? disordered_triangular_disk(compression.network_nodes, compression.network_jitter,
                                         compression.network_k, compression.seed)
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
    const CompressionResult result =
        network ? compress_spring_network(compression, frame) : compress_shell(compression, frame);
    context.count_steps(result.iterations);
    // Moduli for F~ (decision dpm-compress-moduli): the ordered triangular lattice for the network; for the
    // shell, E = k_l (stretching modulus k_l l0 over a wall thickness sigma = l0) and nu = 0.
    const double E = network ? triangular_lattice_young_modulus(compression.network_k) : compression.kl;
    const double nu = network ? triangular_lattice_poisson_ratio : 0.0;
    const double d_tilde = options.D_tilde;

    auto& table = context.table(
        "force.dat",
        {{"delta", "D", "compression delta / D"},
         {"F", "k_c sigma", "force F_a on the top plate"},
         {"F_over_D", "k_c", "F_a / D"},
         {"F_tilde", "1", "F~ = F_a (1 - nu^2)/(E D D~) (2D: force per length over E D, times 1/D~)"},
         {"delta_eq_9_14", "1", "delta~ of eq. (9.14) for the cylinder at this F~ and D~"}});
    std::vector<double> fit_delta, fit_force, fit_delta_cylinder;
    for (const CompressionSample& sample : result.samples) {
        const double f_tilde = sample.force * (1 - nu * nu) / (E * result.diameter * d_tilde);
        const double cylinder = sample.force > 0 ? cylinder_compression(f_tilde, d_tilde) : 0.0;
        table.row({sample.delta_over_d, sample.force, sample.force / result.diameter, f_tilde, cylinder});
        if (sample.delta_over_d <= options.fit_max && sample.force > 0) {
            fit_delta.push_back(sample.delta_over_d);
            fit_force.push_back(sample.force);
            fit_delta_cylinder.push_back(cylinder);
        }
    }
    auto& summary = context.summary();
    summary["diameter"] = result.diameter;
    summary["E"] = E;
    summary["nu"] = nu;
    summary["small_strain_exponent"] =
        value_or_null(fit_power_law_exponent(fit_delta, fit_force, minimum_exponent_points));
    // The exponent of eq. (9.14) over the same forces: its local slope 1 + 1/(1 + ln(pi/(D~^3 F~))) > 1.
    summary["eq_9_14_exponent"] =
        value_or_null(fit_power_law_exponent(fit_delta_cylinder, fit_force, minimum_exponent_points));
    if (network) {
        summary["network_nodes"] = compression.network_nodes;
        summary["network_springs"] = result.springs;
        summary["coordination"] = 2.0 * result.springs / compression.network_nodes;
    }
}

} // namespace

Scene compress2d_scene()
{
    return bound_scene("dpm.compress2d",
                       "DPM sec. 9.3.4: an elastic shell or a spring-network disk compressed between two "
                       "plates, F_a against delta/D, its small-strain exponent and eq. (9.14) (Fig. 9.10)",
                       compress2d_binding(), run_compress2d)
        .needing(compress2d_binding().estimate([](const Compress2dOptions& options) {
            return options.body == Compress2dBody::shell
                       ? dpm_vertex_memory(options.compression.nodes, "vertices (nodes)")
                       : dpm_vertex_memory(options.compression.network_nodes, "nodes (network_nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
