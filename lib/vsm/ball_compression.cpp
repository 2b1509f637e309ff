#include "vsm/ball_compression.hpp"

#include "core/errors.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/stability.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace softgrain::vsm {

namespace {

constexpr int sphere_label = 3; // ball_octant_domain's label of the spherical surface

// The top plate moving from height `from` at t0 to `to` at t0 + duration, then resting [m, s].
struct PlateMotion
{
    double from, to, t0, duration;
    double height(double t) const
    {
        return t >= t0 + duration ? to : from + (to - from) * (t - t0) / duration;
    }
    double end() const { return t0 + duration; }
};

// The stiffest plate spring over its particle's mass, max_a k_ab / m_a [1/s^2], k_ab = c_pen E A_ab / L_ab.
double plate_frequency_squared(const Model& model, double penalty)
{
    double largest = 0;
    for (std::size_t a = 0; a < model.size(); ++a)
        for (const Neighbour& nb : model.cells().neighbours[a])
            if (nb.ghost() && nb.label == sphere_label)
                largest = std::max(largest,
                                   penalty * model.material().young * nb.area / nb.length / model.mass()[a]);
    return largest;
}

// The largest force on a particle [N].
double largest_force(const Points<3>& f)
{
    return f.colwise().norm().maxCoeff();
}

// Damped leapfrog from rest until the unbalanced and the damping force of every particle are below
// tolerance times the plate load: the number of steps taken and the final residual over the load.
struct Relaxation
{
    long steps = 0;
    double residual = 0;
};

Relaxation relax(const Model& model, Leapfrog& integrator, double damping, double tolerance,
                 double force_scale, long budget)
{
    constexpr int check_every = 20;
    const Eigen::VectorXd mass = [&] {
        Eigen::VectorXd m(3 * static_cast<Eigen::Index>(model.size()));
        for (std::size_t a = 0; a < model.size(); ++a)
            m.segment<3>(3 * static_cast<Eigen::Index>(a)).setConstant(model.mass()[a]);
        return m;
    }();
    const long start = integrator.state().step;
    for (;;) {
        for (int s = 0; s < check_every; ++s)
            integrator.step();
        const Points<3> x = integrator.positions();
        const double t = integrator.state().t;
        // Without a contact the ball is at rest under no load: converged when its forces are round-off,
        // below 1e-9 E h^2 (h^2 ~ the area of a Voronoi face).
        const double load = std::max(model.plate_load(x, t, 0).force, 1e-9 * force_scale);
        const Eigen::VectorXd drag = damping * mass.cwiseProduct(integrator.state().v);
        const double residual =
            std::max(largest_force(model.forces(x, t)),
                     largest_force(Eigen::Map<const Points<3>>(drag.data(), 3, drag.size() / 3)));
        const long steps = integrator.state().step - start;
        if (residual <= tolerance * load) return {steps, residual / load};
        if (steps >= budget) {
            std::ostringstream m;
            m << "the ball did not relax within " << budget << " steps: largest unbalanced force " << residual
              << " N against the plate load " << load << " N (relax_tolerance " << tolerance << ")";
            throw NumericalError(m.str(), integrator.state().step,
                                 "a time step above the stability limit (cfl too large: the plate springs "
                                 "count, sqrt(m_a/k_ab)) keeps the ball oscillating; else the damping is far "
                                 "from critical");
        }
    }
}

} // namespace

Points<3> octant_lattice(double R, int per_radius)
{
    const double h = R / per_radius;
    std::vector<Vec3> points;
    for (int k = 0; k < per_radius; ++k)
        for (int j = 0; j < per_radius; ++j)
            for (int i = 0; i < per_radius; ++i) {
                const Vec3 X = h * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (X.norm() <= R - 0.5 * h) points.push_back(X);
            }
    Points<3> X(3, static_cast<Eigen::Index>(points.size()));
    for (std::size_t p = 0; p < points.size(); ++p)
        X.col(static_cast<Eigen::Index>(p)) = points[p];
    return X;
}

std::vector<double> ball_compressions(const BallCompressionSetup& setup)
{
    std::vector<double> out;
    for (int s = 0; s < setup.compressions; ++s)
        out.push_back(setup.compressions == 1
                          ? setup.delta_max
                          : setup.delta_min * std::pow(setup.delta_max / setup.delta_min,
                                                       double(s) / (setup.compressions - 1)));
    return out;
}

BallCompressionResult compress_ball(const BallCompressionSetup& setup,
                                    const std::function<void(const BallCompressionSample&)>& observe)
{
    const double R = 0.5 * setup.diameter;
    const Domain domain = ball_octant_domain(R);
    const Points<3> X = octant_lattice(R, setup.per_radius);
    // The top plate, lowered between relaxations at a constant speed (the model reads it through the plate).
    const auto plate = std::make_shared<PlateMotion>(PlateMotion{R, R, 0, 0});
    BoundaryConditions bc;
    bc.kind = {BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::free};
    bc.displacement = [](int, const Vec3&, double) { return Vec3::Zero(); };
    bc.plates = {RigidPlate{sphere_label, Vec3::UnitZ(), [plate](double t) { return plate->height(t); },
                            setup.penalty}};
    const double h = R / setup.per_radius;
    const Model model(build_reference_cells(X, domain, 2 * h), domain, bc, setup.material, setup.options);

    BallCompressionResult result;
    result.particles = static_cast<int>(model.size());
    double volume = 0;
    for (double V : model.cells().volume)
        volume += V;
    result.volume_excess = volume / domain.volume - 1;
    result.dt_elastic_limit = predicted_time_step_limit(model);
    const double elastic_time =
        model.min_branch_length() / effective_wave_speed(setup.material, setup.options);
    result.dt =
        setup.cfl * std::min(elastic_time, 1 / std::sqrt(plate_frequency_squared(model, setup.penalty)));
    const double damping = setup.damping * setup.material.shear_wave_speed() / R;
    Leapfrog integrator(model, X, Points<3>::Zero(3, X.cols()), result.dt, damping,
                        setup.time_step_check ? TimeStepCheck::refuse_above_limit : TimeStepCheck::off);
    // Budget of one relaxation: 200 damping times, ample for a relaxation at rate c/2 to 1e-3 (about 14).
    const auto budget = static_cast<long>(200 / (damping * result.dt)) + 1;
    const double plate_speed = setup.plate_speed * setup.material.shear_wave_speed();
    for (double delta_over_d : ball_compressions(setup)) {
        const double target = R - 0.5 * delta_over_d * setup.diameter;
        const double t = integrator.state().t;
        *plate = PlateMotion{plate->height(t), target, t, (plate->height(t) - target) / plate_speed};
        while (integrator.state().t < plate->end())
            integrator.step();
        const Relaxation relaxation =
            relax(model, integrator, damping, setup.relax_tolerance, setup.material.young * h * h, budget);
        const Model::PlateLoad load = model.plate_load(integrator.positions(), integrator.state().t, 0);
        BallCompressionSample sample;
        sample.delta_over_d = delta_over_d;
        sample.force = 4 * load.force; // the octant carries a quarter of the plate
        sample.contacts = load.contacts;
        sample.steps = relaxation.steps;
        sample.residual = relaxation.residual;
        if (observe) observe(sample);
        result.samples.push_back(sample);
    }
    result.steps = integrator.state().step;
    return result;
}

} // namespace softgrain::vsm
