#include "dpm/protocols/compress.hpp"

#include "core/errors.hpp"
#include "core/fire.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/laws/spring_network.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace softgrain::dpm {

namespace {

// Body energy plus the plates' repulsion (normal to axis Dim - 1), with gradient.
template <int Dim>
struct BetweenPlates
{
    const BodyEnergy& body;
    double kp, half_sigma, top;
    double energy(const Eigen::VectorXd& x, Eigen::VectorXd* gradient, double* top_force = nullptr,
                  int* top_contacts = nullptr) const
    {
        double u = body(x, gradient);
        if (top_force) *top_force = 0;
        if (top_contacts) *top_contacts = 0;
        for (Eigen::Index v = 0; v < x.size() / Dim; ++v) {
            const std::array<int, 1> point{static_cast<int>(v)};
            const double height = x(Dim * v + Dim - 1);
            if (height < half_sigma) // Theta(sigma/2 - r), bottom plate at height 0
                u += add_local_term<Dim, 1>(PlateEnergy{kp, half_sigma, 0.0, 1.0}, point,
                                            gather<Dim, 1>(x, point), gradient, nullptr);
            if (top - height < half_sigma) { // top plate
                u += add_local_term<Dim, 1>(PlateEnergy{kp, half_sigma, top, -1.0}, point,
                                            gather<Dim, 1>(x, point), gradient, nullptr);
                if (top_force) *top_force += kp * (half_sigma - (top - height)); // pushes the plate up
                if (top_contacts) ++*top_contacts;
            }
        }
        return u;
    }
};

} // namespace

std::vector<double> PlateSchedule::deltas() const
{
    if (!compressions.empty()) return compressions;
    std::vector<double> out;
    for (int s = 0; s < steps; ++s)
        out.push_back(delta_min * std::pow(delta_max / delta_min, double(s) / (steps - 1)));
    return out;
}

template <int Dim>
CompressionResult compress_between_plates(Eigen::VectorXd x, const BodyEnergy& body, double sigma,
                                          double lambda_max, const PlateSchedule& o,
                                          const PlateObserver& observe)
{
    const auto heights = x.reshaped(Dim, x.size() / Dim).row(Dim - 1);
    const double lift = 0.5 * sigma - heights.minCoeff();
    for (Eigen::Index v = 0; v < x.size() / Dim; ++v)
        x(Dim * v + Dim - 1) += lift;
    CompressionResult out;
    const double h0 = heights.maxCoeff() + 0.5 * sigma;
    out.diameter = h0;
    FireOptions fire;
    fire.dt_max = 0.5 / std::sqrt(std::max(o.kp, lambda_max));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = o.force_tolerance;
    fire.kinetic_tolerance = o.kinetic_tolerance;
    fire.max_iterations = 5'000'000;
    const std::vector<double> deltas = o.deltas();
    for (int s = 0; s < static_cast<int>(deltas.size()); ++s) {
        const double delta = deltas[s];
        const BetweenPlates<Dim> plates{body, o.kp, 0.5 * sigma, h0 - delta * out.diameter};
        const FireResult r = fire_minimise(
            x,
            [&plates](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
                f.setZero(y.size());
                const double u = plates.energy(y, &f);
                f = -f;
                return u;
            },
            fire);
        out.iterations += r.iterations;
        if (!r.converged)
            throw NumericalError("relaxation between the plates (" + fire_shortfall(r, fire) + ")", s,
                                 "step too large for the body's stiffness");
        double force = 0;
        int contacts = 0;
        plates.energy(x, nullptr, &force, &contacts);
        out.samples.push_back({delta, force, r.iterations, contacts});
        if (observe) observe(x, plates.top, out.samples.back());
    }
    return out;
}

template CompressionResult compress_between_plates<2>(Eigen::VectorXd, const BodyEnergy&, double, double,
                                                      const PlateSchedule&, const PlateObserver&);
template CompressionResult compress_between_plates<3>(Eigen::VectorXd, const BodyEnergy&, double, double,
                                                      const PlateSchedule&, const PlateObserver&);

DpmSystem compression_shell(const CompressionOptions& options, Eigen::VectorXd& x)
{
    const double pi = std::numbers::pi, sigma = 1.0;
    const int n = options.nodes;
    const double R = sigma / (2 * std::sin(pi / n)); // edge = sigma
    const double a0 = 0.5 * n * R * R * std::sin(2 * pi / n);
    ShapeStiffness k;
    k.ka = options.ka * sigma * sigma / (a0 * a0);
    k.kl = options.kl;
    k.kb = options.kb * sigma * sigma;
    DpmSystem system;
    system.add_particle(regular_polygon(n, R, Eigen::Vector2d(0, 0), 0.0), sigma,
                        table_9_1_parameters(ShapeModel::shell, n, a0, minimum_shape_parameter(n), k), x);
    return system;
}

CompressionResult compress_shell(const CompressionOptions& options, const PlateObserver& observe)
{
    Eigen::VectorXd x;
    const DpmSystem system = compression_shell(options, x);
    const double sigma = system.particles.front().sigma;
    const BodyEnergy body = [&system](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return total_energy(system, y, gradient, nullptr);
    };
    return compress_between_plates<2>(x, body, sigma, vibrational_modes(system, x).eigenvalues.maxCoeff(),
                                      options.schedule(), observe);
}

CompressionResult compress_spring_network(const CompressionOptions& options, const PlateObserver& observe)
{
    const SpringNetwork network = disordered_triangular_disk(options.network_nodes, options.network_jitter,
                                                             options.network_k, options.seed);
    const BodyEnergy body = [&network](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return spring_network_energy(network, y, gradient);
    };
    // A node joins at most 6 springs k (lengths ~ 1): lambda_max <= 4 * 6 k / 2 = 12 k (Gershgorin, unit
    // masses).
    CompressionResult out =
        compress_between_plates<2>(network.x, body, 1.0, 12 * options.network_k, options.schedule(), observe);
    out.springs = static_cast<int>(network.springs.size());
    return out;
}

double cylinder_compression(double force_tilde, double d_tilde)
{
    const double pi = std::numbers::pi;
    return 4 * force_tilde * d_tilde / pi * (1 + std::log(pi / (d_tilde * d_tilde * d_tilde * force_tilde)));
}

} // namespace softgrain::dpm
