#include "dpm/protocols/shear_friction.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace softgrain::dpm {

double rough_friction_maximum(double C, int nodes)
{
    const double s = 1.0 / (C * std::sin(std::numbers::pi / nodes));
    return 1.0 / std::sqrt(s * s - 1.0);
}

namespace {

Eigen::Vector2d centre_of_mass(const Eigen::VectorXd& x, const Particle& p)
{
    return x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count).rowwise().mean();
}

} // namespace

ContactForce contact_force_on_mu(const DpmSystem& system, const Eigen::VectorXd& x)
{
    const Particle &beta = system.particles[0], &mu = system.particles[1];
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    const double energy = total_energy(system, x, &g, nullptr, interaction_part);
    const Eigen::Vector2d force =
        -g.segment(2 * mu.first, 2 * mu.count).reshaped(2, mu.count).rowwise().sum();
    const Eigen::Vector2d normal = (centre_of_mass(x, mu) - centre_of_mass(x, beta)).normalized();
    const Eigen::Vector2d tangent(-normal.y(), normal.x()); // n x t = z
    return {force.dot(normal), force.dot(tangent), energy};
}

ShearTestResult simple_shear_test(const ShearTestOptions& options, const ShearStepObserver& observe)
{
    const double pi = std::numbers::pi, sigma = 1.0;
    const int n = options.nodes;
    const double R = options.C * sigma;
    const double half_edge = R * std::sin(pi / n);
    if (sigma * (1 - options.overlap) <= half_edge)
        throw InputError("C = " + std::to_string(options.C) +
                         " with overlap = " + std::to_string(options.overlap) +
                         ": the groove vertex would touch only one vertex; need C sin(pi/N) < 1 - overlap");
    const double a0 = 0.5 * n * R * R * std::sin(2 * pi / n); // area of the regular N-gon
    const double A0 = options.A0.value_or(minimum_shape_parameter(n));
    if (A0 < minimum_shape_parameter(n)) // no N-gon has a smaller shape parameter
        throw InputError("A0 = " + std::to_string(A0) +
                         " is below A_min(N) = " + std::to_string(minimum_shape_parameter(n)));

    ShapeParameters shape;
    shape.ka = options.ka * sigma * sigma / (a0 * a0);
    shape.a0 = a0;
    shape.kl = options.kl;
    shape.l0 = std::sqrt(4 * pi * a0 * A0) / n;
    shape.kb = options.kb * sigma * sigma;
    shape.theta0 = 2 * pi / n;

    // Groove position: mu's bottom vertex at distance sigma (1 - overlap) from beta's two top vertices.
    const double top = R * std::cos(pi / n); // height of beta's flat top edge above its centre (N even)
    const double h = R + top + std::sqrt(std::pow(sigma * (1 - options.overlap), 2) - half_edge * half_edge);
    ShearTestResult result;
    DpmSystem& system = result.system;
    system.interaction = options.interaction;
    system.kc = 1.0;
    Eigen::VectorXd& x = result.x;
    const Eigen::Vector2d beta_centre(0, 0), mu_start(0, h);
    system.add_particle(regular_polygon(n, R, beta_centre, -pi / 2 - pi / n), sigma, shape, x); // flat bottom
    system.add_particle(regular_polygon(n, R, mu_start, -pi / 2), sigma, shape, x);             // vertex down
    if (options.kb == 0) {
        Rng rng(options.seed);
        for (Eigen::Index i = 0; i < x.size(); ++i)
            x(i) += 1e-3 * shape.l0 * rng.normal(1.0);
    }
    const Particle beta = system.particles[0], mu = system.particles[1];
    for (int v : {0, 1})
        system.anchors.push_back({beta.first + v, x.segment<2>(2 * (beta.first + v)), options.k_constraint});
    const int top_vertex = mu.first + n / 2;
    for (int v : {top_vertex - 1, top_vertex, top_vertex + 1})
        system.anchors.push_back({v, x.segment<2>(2 * v), options.k_constraint});

    // FIRE's velocity Verlet (unit masses) is stable for dt < 2/sqrt(lambda_max); lambda_max of the
    // dynamical matrix at the start (shape terms and anchors dominate it) sets dt_max = 1/sqrt(lambda_max).
    FireOptions fire;
    const double lambda_max = vibrational_modes(system, x).eigenvalues.maxCoeff();
    fire.dt_max = 1.0 / std::sqrt(lambda_max);
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-11;

    // Rest shapes (decision dpm-shear-rest-shapes): each particle relaxes alone (no interaction, anchors
    // on); a shell at A0 = A_min stays the regular polygon, a floppy particle with A0 > A_min does not. Then
    // mu is moved so that the vertical gap between its lowest and beta's highest vertex is that of the
    // regular polygons in the groove position, and to its start x_start D_beta.
    system.interaction = InteractionKind::none;
    const FireResult rest = relax_fire(system, x, fire);
    system.interaction = options.interaction;
    result.iterations += rest.iterations;
    if (!rest.converged)
        throw NumericalError("relaxation of the rest shapes (" + fire_shortfall(rest, fire) + ")", 0,
                             "stiff shape terms; lower dt_max");
    const auto ys = [&x](const Particle& q) {
        return x.segment(2 * q.first, 2 * q.count).reshaped(2, q.count).row(1);
    };
    const auto beta_x = x.segment(2 * beta.first, 2 * beta.count).reshaped(2, beta.count).row(0);
    result.d_beta = beta_x.maxCoeff() - beta_x.minCoeff() + sigma; // D_beta (section 9.3.3)
    const double groove_gap = h - R - top;
    const Eigen::Vector2d shift(options.x_start * result.d_beta,
                                ys(beta).maxCoeff() + groove_gap - ys(mu).minCoeff());
    for (int v = mu.first; v < mu.first + mu.count; ++v)
        x.segment<2>(2 * v) += shift;
    for (std::size_t a = 2; a < system.anchors.size(); ++a)
        system.anchors[a].position += shift;
    const double beta_mid = 0.5 * (system.anchors[0].position.x() + system.anchors[1].position.x());
    result.configurations.reserve(static_cast<std::size_t>((options.x_end - options.x_start) / options.dx) +
                                  2);

    const int steps = static_cast<int>(std::floor((options.x_end - options.x_start) / options.dx + 1e-9));
    for (int step = 0; step <= steps; ++step) {
        if (step > 0)
            for (std::size_t a = 2; a < system.anchors.size(); ++a)
                system.anchors[a].position.x() += options.dx * result.d_beta;
        const FireResult relaxed = relax_fire(system, x, fire);
        result.iterations += relaxed.iterations;
        if (!relaxed.converged)
            throw NumericalError("relaxation of the shear step (" + fire_shortfall(relaxed, fire) + ")", step,
                                 "stiff shape terms against soft contacts; lower dt_max");
        const ContactForce force = contact_force_on_mu(system, x);
        ShearSample sample;
        sample.x_over_d = (system.anchors[3].position.x() - beta_mid) / result.d_beta;
        sample.normal_force = force.normal;
        sample.tangential_force = force.tangential;
        sample.energy = relaxed.energy;
        sample.iterations = relaxed.iterations;
        result.configurations.push_back({sample.x_over_d, x});
        if (sample.normal_force > 0) sample.mu_eff = sample.tangential_force / sample.normal_force;
        if (observe) observe(system, x, sample);
        if (sample.normal_force <= 0) continue; // not in contact
        if (result.samples.empty() || sample.mu_eff > result.mu_eff_max) {
            result.mu_eff_max = sample.mu_eff;
            result.x_at_max = sample.x_over_d;
            result.x_star = x;
        }
        result.samples.push_back(sample);
    }
    return result;
}

} // namespace softgrain::dpm
