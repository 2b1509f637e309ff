#include "dpm/compress.hpp"

#include "core/errors.hpp"
#include "dpm/modes.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace softgrain::dpm {

namespace {

// Shape energy of the particle plus the plates' repulsion, with gradient (FIRE needs no Hessian).
struct BetweenPlates
{
    const DpmSystem& system;
    double kp, half_sigma, top;
    double energy(const Eigen::VectorXd& x, Eigen::VectorXd* gradient, double* top_force) const
    {
        double u = total_energy(system, x, gradient, nullptr);
        if (top_force) *top_force = 0;
        for (int v = 0; v < system.vertex_count(); ++v) {
            const std::array<int, 1> point{v};
            const double y = x(2 * v + 1);
            if (y < half_sigma) // Theta(sigma/2 - r), bottom plate at y = 0
                u += add_local_term<2, 1>(PlateEnergy{kp, half_sigma, 0.0, 1.0}, point,
                                          gather<2, 1>(x, point), gradient, nullptr);
            if (top - y < half_sigma) { // top plate
                u += add_local_term<2, 1>(PlateEnergy{kp, half_sigma, top, -1.0}, point,
                                          gather<2, 1>(x, point), gradient, nullptr);
                if (top_force) *top_force += kp * (half_sigma - (top - y)); // pushes the plate up
            }
        }
        return u;
    }
};

} // namespace

CompressionResult compress_shell(const CompressionOptions& o)
{
    const double pi = std::numbers::pi, sigma = 1.0;
    const int n = o.nodes;
    const double R = sigma / (2 * std::sin(pi / n)); // edge = sigma
    const double a0 = 0.5 * n * R * R * std::sin(2 * pi / n);
    ShapeStiffness k;
    k.ka = o.ka * sigma * sigma / (a0 * a0);
    k.kl = o.kl;
    k.kb = o.kb * sigma * sigma;
    DpmSystem system;
    Eigen::VectorXd x;
    system.add_particle(regular_polygon(n, R, Eigen::Vector2d(0, R + 0.5 * sigma), 0.0), sigma,
                        table_9_1_parameters(ShapeModel::shell, n, a0, minimum_shape_parameter(n), k), x);
    CompressionResult out;
    out.diameter = 2 * R + sigma;
    const double h0 = out.diameter;

    FireOptions fire;
    fire.dt_max = 0.5 / std::sqrt(std::max(o.kp, vibrational_modes(system, x).eigenvalues.maxCoeff()));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-12;
    for (int s = 0; s < o.steps; ++s) {
        const double delta = o.delta_min * std::pow(o.delta_max / o.delta_min, double(s) / (o.steps - 1));
        const BetweenPlates plates{system, o.kp, 0.5 * sigma, h0 - delta * out.diameter};
        const FireResult r = fire_minimise(
            x,
            [&plates](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
                f.setZero(y.size());
                const double u = plates.energy(y, &f, nullptr);
                f = -f;
                return u;
            },
            fire);
        out.iterations += r.iterations;
        if (!r.converged)
            throw NumericalError("FIRE relaxation between the plates (force rms " +
                                     std::to_string(r.force_rms) + ")",
                                 s, "step too large for the shell stiffness");
        double force = 0;
        plates.energy(x, nullptr, &force);
        out.samples.push_back({delta, force, r.iterations});
    }
    return out;
}

} // namespace softgrain::dpm
