#include "vsm/l_block.hpp"

#include "core/errors.hpp"
#include "vsm/dynamics.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace softgrain::vsm {

namespace {
constexpr double arm = 6, height = 10, thickness = 3, load_end = 5;

Points<3> l_block_lattice(double h)
{
    const int nx = static_cast<int>(std::lround(arm / h)), ny = static_cast<int>(std::lround(height / h)),
              nz = static_cast<int>(std::lround(thickness / h));
    if (std::abs(nx * h - arm) > 1e-9 || std::abs(ny * h - height) > 1e-9 ||
        std::abs(nz * h - thickness) > 1e-9)
        throw InputError("spacing = " + std::to_string(h) + " must divide 6, 10 and 3 m (e.g. 1, 0.5, 0.25)");
    std::vector<Vec3> points;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k) {
                const Vec3 X = h * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (X.x() < thickness || X.y() < thickness) points.push_back(X);
            }
    Points<3> X(3, static_cast<Eigen::Index>(points.size()));
    for (std::size_t p = 0; p < points.size(); ++p)
        X.col(static_cast<Eigen::Index>(p)) = points[p];
    return X;
}
} // namespace

double l_block_pulse(double t)
{
    return std::max(2.5 - std::abs(t - 2.5), 0.0);
}

LBlockResult run_l_block(const LBlockSetup& setup, long stride,
                         const std::function<void(const LBlockSample&, const Points<3>&)>& observe,
                         const StepObserver& on_step)
{
    const Domain domain = l_block_domain(arm, height, thickness);
    const Points<3> X = l_block_lattice(setup.spacing);
    BoundaryConditions bc;
    bc.kind.assign(3, BoundaryKind::free); // labels: 0 face X1 = 6, 1 face X2 = 10, 2 the rest
    const Vec3 load = setup.load;
    bc.traction = [load](int label, const Vec3&, double t) {
        const double p = l_block_pulse(t);
        return Vec3(label == 0 ? Vec3(p * load) : label == 1 ? Vec3(-p * load) : Vec3::Zero());
    };
    const Model model(build_reference_cells(X, domain, 2 * setup.spacing), domain, bc, setup.material,
                      setup.options);

    const double dt_limit = setup.cfl * model.min_branch_length() / setup.material.p_wave_speed();
    // An integer number of steps to the end of loading, so that t = 5 s is a sample time.
    const long load_steps = static_cast<long>(std::ceil(load_end / dt_limit));
    const double dt = load_end / static_cast<double>(load_steps);
    const long steps = static_cast<long>(std::ceil(setup.end_time / dt));
    Leapfrog integrator(model, X, Points<3>::Zero(3, X.cols()), dt, 0.0,
                        setup.time_step_check ? TimeStepCheck::refuse_above_limit : TimeStepCheck::off);

    const auto sample = [&]() {
        const Points<3> x = integrator.positions();
        const Points<3> v = integrator.half_step_velocities();
        LBlockSample out{integrator.state().t, Vec3::Zero(), Vec3::Zero()};
        for (Eigen::Index a = 0; a < x.cols(); ++a) {
            const double m = model.mass()[static_cast<std::size_t>(a)];
            out.linear += m * v.col(a);
            out.angular += m * Vec3(x.col(a)).cross(Vec3(v.col(a)));
        }
        return std::make_pair(out, x);
    };
    LBlockResult r;
    r.particles = static_cast<int>(X.cols());
    r.dt = dt;
    r.steps = steps;
    r.impulse_scale = thickness * thickness * 6.25 * load.norm(); // A * int p dt * |load|, int p dt = 6.25 s
    const auto [initial, x0] = sample();
    const Vec3 p0 = initial.linear;
    observe(initial, x0); // t = 0: the reference shape and zero momentum
    if (on_step) on_step(model, integrator);
    for (long k = 1; k <= steps; ++k) {
        integrator.step();
        if (on_step) on_step(model, integrator);
        const bool at_load_end = k == load_steps;
        const auto [state, x] = sample(); // every step: O(N), cheap next to the forces
        r.linear_momentum_drift = std::max(r.linear_momentum_drift, (state.linear - p0).norm());
        if (at_load_end) r.angular_momentum_after_load = state.angular;
        if (k >= load_steps)
            r.angular_momentum_drift_after_load = std::max(
                r.angular_momentum_drift_after_load, (state.angular - r.angular_momentum_after_load).norm());
        if (k % stride == 0 || k == steps || at_load_end) observe(state, x);
    }
    return r;
}

} // namespace softgrain::vsm
