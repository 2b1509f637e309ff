// dpm.compress3d: one 3D body squeezed between two plates (section 9.3.4, Fig. 9.11): the elastic tetrahedra
// of eqs. (9.15)-(9.17), an elastic shell (eq. 9.2) or a spring-network ball; F~ = F_a (1 - nu^2)/(E D^2)
// against delta~ = delta/D, and the exponents of F~ ~ delta~^alpha at small and large compression and while
// the pole vertex alone touches the plate (decision dpm-compress3d-windows).
#include "dpm/scenes/scenes.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/shape_energy3d.hpp"
#include "dpm/laws/spring_network.hpp"
#include "dpm/protocols/compress3d.hpp"

#include <cmath>
#include <stdexcept>

namespace softgrain::dpm {

namespace {

// The exponent fitted to the samples with delta/D in [low, high] and F > 0.
std::optional<double> exponent_in_window(const CompressionResult& compression, double low, double high)
{
    std::vector<double> delta, force;
    for (const CompressionSample& sample : compression.samples)
        if (sample.delta_over_d >= low * (1 - 1e-12) && sample.delta_over_d <= high * (1 + 1e-12) &&
            sample.force > 0) {
            delta.push_back(sample.delta_over_d);
            force.push_back(sample.force);
        }
    return fit_power_law_exponent(delta, force, minimum_exponent_points);
}

// The exponent fitted to the samples in which only the pole vertex touches the top plate.
std::optional<double> pole_contact_exponent(const CompressionResult& compression)
{
    std::vector<double> delta, force;
    for (const CompressionSample& sample : compression.samples)
        if (sample.top_contacts == 1) {
            delta.push_back(sample.delta_over_d);
            force.push_back(sample.force);
        }
    return fit_power_law_exponent(delta, force, minimum_exponent_points);
}

enum class Compress3dBody { tetrahedra, shell, spring_network };

// dpm.compress3d's options: the compression, the body, and the report's fit windows.
struct Compress3dOptions
{
    Compression3dOptions compression = scene_compression_defaults();
    Compress3dBody body = Compress3dBody::tetrahedra;
    double small_fit_max = 3e-3;          // [D]
    double fit_min = 0.05, fit_max = 0.2; // [D]

    // The scene's defaults where they differ from the library's.
    static Compression3dOptions scene_compression_defaults()
    {
        Compression3dOptions defaults;
        defaults.schedule.delta_min = 1e-3;
        defaults.schedule.steps = 24;
        defaults.schedule.force_tolerance = 1e-8;
        return defaults;
    }
};

// `low` < `high`, else an InputError naming both keys.
void require_below(const std::string& low_key, double low, const std::string& high_key, double high)
{
    if (low >= high)
        throw InputError("parameter '" + low_key + "' = '" + std::to_string(low) + "' is not below " +
                         high_key + " = " + std::to_string(high) + "; allowed: " + low_key + " < " +
                         high_key);
}

OptionBinding<Compress3dOptions> compress3d_binding()
{
    const auto body = [](auto... field) { return path(&Compress3dOptions::compression, field...); };
    const auto schedule = [](auto field) {
        return path(&Compress3dOptions::compression, &Compression3dOptions::schedule, field);
    };
    OptionBinding<Compress3dOptions> binding;
    binding.choice(&Compress3dOptions::body, "model",
                   {{"tetrahedra", Compress3dBody::tetrahedra},
                    {"shell", Compress3dBody::shell},
                    {"spring_network", Compress3dBody::spring_network}},
                   "elastic tetrahedra (Fig. 9.11c, eqs. 9.15-9.17), elastic shell (Fig. 9.11b, "
                   "eq. 9.2) or spring-network ball (Fig. 9.11a)");
    binding.word(body(&Compression3dOptions::mesh), "mesh",
                 {"icosahedron", "geodesic42", "geodesic162", "geodesic642", "geodesic2562"},
                 "tetrahedra and shell: surface mesh (N = 12, 42, 162, 642, 2562; paper's shell: 162)");
    binding
        .real(body(&Compression3dOptions::E), "E", "k_c/sigma",
              "tetrahedra: Young's modulus of each tetrahedron")
        .positive();
    binding.real(body(&Compression3dOptions::nu), "nu", "1", "tetrahedra: Poisson ratio")
        .at_least(0.0)
        .below(0.5);
    binding
        .real(body(&Compression3dOptions::kv), "kv", "k_c/sigma^4",
              "shell: volume stiffness k_v of eq. (9.2)")
        .positive();
    binding
        .real(body(&Compression3dOptions::ka), "ka", "k_c/sigma^2",
              "shell: face-area stiffness k_a of eq. (9.2)")
        .positive();
    binding
        .real(body(&Compression3dOptions::kb), "kb", "k_c sigma^2",
              "shell: bending stiffness k_b of eq. (9.2)")
        .positive();
    binding
        .integer(body(&Compression3dOptions::network_nodes), "network_nodes", "1",
                 "network: nodes (paper: 3765)")
        .at_least(50);
    binding
        .real(body(&Compression3dOptions::cutoff), "cutoff", "node spacing",
              "network: springs join nodes closer than this")
        .positive();
    binding.seed(body(&Compression3dOptions::seed), "seed", "network: seed of the interior node placement");
    binding.real(schedule(&PlateSchedule::kp), "kp", "k_c", "plate-vertex spring k_p (paper: 4 k_c)")
        .positive();
    binding.integer(schedule(&PlateSchedule::steps), "steps", "1", "compression steps, log-spaced")
        .at_least(3);
    binding.real(schedule(&PlateSchedule::delta_min), "delta_min", "D", "smallest compression delta/D")
        .positive();
    binding.real(schedule(&PlateSchedule::delta_max), "delta_max", "D", "largest compression delta/D")
        .positive()
        .below(0.5);
    binding
        .real(&Compress3dOptions::small_fit_max, "small_fit_max", "D",
              "small_strain_exponent: fit over delta/D from delta_min up to this")
        .positive();
    binding
        .real(&Compress3dOptions::fit_min, "fit_min", "D",
              "large_strain_exponent: fit over delta/D from this ...")
        .positive();
    binding.real(&Compress3dOptions::fit_max, "fit_max", "D", "... up to this").positive();
    binding
        .real(schedule(&PlateSchedule::force_tolerance), "force_tolerance", "k_c sigma",
              "FIRE stops at this rms force per degree of freedom")
        .positive();
    binding.check([](const Compress3dOptions& options) {
        const PlateSchedule& plates = options.compression.schedule;
        require_below("delta_min", plates.delta_min, "delta_max", plates.delta_max);
        require_below("fit_min", options.fit_min, "fit_max", options.fit_max);
    });
    return binding;
}

// ParaView frames, one per compression step, delta/D as the time value: the body (the surface mesh of the
// tetrahedra or the shell, the network's nodes and springs) and the plates, with field data delta_over_D and
// force.
BodyObserver compression_frames(const Compress3dOptions& options, RunContext& context)
{
    const Compression3dOptions& compression = options.compression;
    const bool network = options.body == Compress3dBody::spring_network;
    const TriangleMesh mesh = network ? TriangleMesh{} : compression_mesh(compression.mesh);
    const SpringNetwork springs =
        network ? disordered_sphere_network(compression.network_nodes, compression.cutoff,
                                            compression.network_k, compression.seed)
                : SpringNetwork{};
    // v0: the volume of the rest mesh (the shell's preferred volume, the tetrahedra's reference).
    const double v0 = network ? 1.0 : mesh_volume(mesh, mesh_coordinates(mesh), 0);
    return [mesh, springs, v0, network, &context](const Eigen::VectorXd& x, double top,
                                                  const CompressionSample& sample,
                                                  const Eigen::VectorXd& gradient) {
        if (!context.vtk()->next()) return;
        vtk::PolyData body =
            network ? spring_network_body(springs, x)
                    : mesh_particles({{&mesh, 0, 1.0, v0, Eigen::Vector3d::Zero()}}, x, gradient);
        const Eigen::Matrix3Xd points = x.reshaped(3, x.size() / 3);
        const Eigen::Vector3d low = points.rowwise().minCoeff(), high = points.rowwise().maxCoeff();
        std::vector<vtk::Part> parts{{"particles", std::move(body)},
                                     {"plates", plates3d((low.head<2>().array() - 1).matrix(),
                                                         (high.head<2>().array() + 1).matrix(), 0.0, top)}};
        for (auto& part : parts) {
            part.data.field("delta_over_D", sample.delta_over_d);
            part.data.field("force", sample.force);
        }
        context.vtk()->write(sample.delta_over_d, parts);
    };
}

// The body chosen, compressed between the plates (compress3d.hpp), each step handed to `observe`.
Compression3dResult compress_body(const Compress3dOptions& options, const BodyObserver& observe)
{
    switch (options.body) {
    case Compress3dBody::tetrahedra:
        return compress3d_tetrahedra(options.compression, observe);
    case Compress3dBody::shell:
        return compress3d_shell(options.compression, observe);
    case Compress3dBody::spring_network:
        return compress3d_network(options.compression, observe);
    }
    throw std::logic_error("compress_body: not a Compress3dBody");
}

void report_compress3d(const Compress3dOptions& options, const Compression3dResult& result,
                       RunContext& context)
{
    const CompressionResult& compression = result.compression;
    const std::vector<CompressionSample>& samples = compression.samples;
    context.count_steps(compression.iterations);

    const double scale =
        (1 - result.nu * result.nu) / (result.E * compression.diameter * compression.diameter);
    auto& table = context.table(
        "force.dat", {{"delta", "D", "compression delta~ = delta / D"},
                      {"F", "k_c sigma", "force F_a on the top plate"},
                      {"F_tilde", "1", "F~ = F_a (1 - nu^2)/(E D^2)"},
                      {"local_exponent", "1", "d ln F / d ln delta between this and the previous step"},
                      {"contacts", "1", "vertices touching the top plate"},
                      {"iterations", "1", "FIRE iterations of this step"}});
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const CompressionSample& sample = samples[k];
        double local = std::nan("");
        if (k > 0 && sample.force > 0 && samples[k - 1].force > 0)
            local = std::log(sample.force / samples[k - 1].force) /
                    std::log(sample.delta_over_d / samples[k - 1].delta_over_d);
        table.row({sample.delta_over_d, sample.force, sample.force * scale, local,
                   double(sample.top_contacts), double(sample.iterations)});
    }
    auto& summary = context.summary();
    summary["diameter"] = compression.diameter;
    summary["E"] = result.E;
    summary["nu"] = result.nu;
    summary["vertices"] = result.vertices;
    summary["small_strain_exponent"] = value_or_null(
        exponent_in_window(compression, options.compression.schedule.delta_min, options.small_fit_max));
    summary["large_strain_exponent"] =
        value_or_null(exponent_in_window(compression, options.fit_min, options.fit_max));
    summary["pole_contact_exponent"] = value_or_null(pole_contact_exponent(compression));
    summary["small_strain_stiffness"] = samples.front().force * scale / samples.front().delta_over_d;
    summary["contacts_at_max"] = samples.back().top_contacts;
    summary["F_tilde_at_max"] = samples.back().force * scale;
    // The whole curve, for comparisons against stored references (reproductions/compare, compare-solid-*).
    std::vector<double> delta_tilde, force_tilde;
    for (const CompressionSample& sample : samples) {
        delta_tilde.push_back(sample.delta_over_d);
        force_tilde.push_back(sample.force * scale);
    }
    summary["delta_tilde"] = delta_tilde;
    summary["F_tilde"] = force_tilde;
    if (options.body == Compress3dBody::spring_network) {
        summary["network_springs"] = result.springs;
        summary["coordination"] = 2.0 * result.springs / result.vertices;
    }
}

void run_compress3d(const Compress3dOptions& options, RunContext& context)
{
    if (options.body == Compress3dBody::spring_network) context.record_seed(options.compression.seed);
    const BodyObserver observe = context.vtk() ? compression_frames(options, context) : BodyObserver{};
    report_compress3d(options, compress_body(options, observe), context);
}

} // namespace

Scene compress3d_scene()
{
    return bound_scene("dpm.compress3d",
                       "DPM sec. 9.3.4: elastic tetrahedra (eqs. 9.15-9.17), an elastic shell or a "
                       "spring-network ball "
                       "compressed between two plates, F~ against delta/D and its exponents (Fig. 9.11)",
                       compress3d_binding(), run_compress3d)
        .advised_by({"compare",
                     "compare-solid-work-precision",
                     "method_index",
                     {"tetrahedra", "spring_network"},
                     "",
                     "",
                     "vertices",
                     "surface vertices + 1 (tetrahedra) or nodes (network)",
                     "fe_error_max",
                     "largest |F~/F~_FE - 1| over 0.01 <= delta/D <= 0.2 against the finite-element "
                     "ball of the same law and nu (data/compare/solid_fe.toml)"})
        .needing(compress3d_binding().estimate([](const Compress3dOptions& options) {
            // The spring network's Newton steps use its dense Hessian; the meshes are bounded.
            if (options.body != Compress3dBody::spring_network) return MemoryEstimate{};
            return dense_matrix_memory(3.0 * options.compression.network_nodes, 1, "3 x network_nodes");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
