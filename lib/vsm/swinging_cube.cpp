#include "vsm/swinging_cube.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/particle_layouts.hpp"
#include "vsm/stability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace softgrain::vsm {

double SwingingCube::wave_number() const
{
    return std::numbers::pi / (2 * length);
}

double SwingingCube::angular_frequency() const
{
    return std::sqrt(3.0) * wave_number() * material.shear_wave_speed();
}

Vec3 SwingingCube::displacement(const Vec3& X, double t) const
{
    const double k = wave_number();
    const Vec3 s(std::sin(k * X.x()), std::sin(k * X.y()), std::sin(k * X.z()));
    const Vec3 c(std::cos(k * X.x()), std::cos(k * X.y()), std::cos(k * X.z()));
    return std::cos(angular_frequency() * t) * Vec3(amplitude.x() * s.x() * c.y() * c.z(),
                                                    amplitude.y() * c.x() * s.y() * c.z(),
                                                    amplitude.z() * c.x() * c.y() * s.z());
}

Mat3 SwingingCube::displacement_gradient(const Vec3& X, double t) const
{
    const double k = wave_number();
    const Vec3 s(std::sin(k * X.x()), std::sin(k * X.y()), std::sin(k * X.z()));
    const Vec3 c(std::cos(k * X.x()), std::cos(k * X.y()), std::cos(k * X.z()));
    Mat3 G;
    G << amplitude.x() * c.x() * c.y() * c.z(), -amplitude.x() * s.x() * s.y() * c.z(),
        -amplitude.x() * s.x() * c.y() * s.z(), //
        -amplitude.y() * s.x() * s.y() * c.z(), amplitude.y() * c.x() * c.y() * c.z(),
        -amplitude.y() * c.x() * s.y() * s.z(), //
        -amplitude.z() * s.x() * c.y() * s.z(), -amplitude.z() * c.x() * s.y() * s.z(),
        amplitude.z() * c.x() * c.y() * c.z();
    return k * std::cos(angular_frequency() * t) * G;
}

namespace {

SwingingCubeError measure_error(const SwingingCube& cube, const Points<3>& X, const Points<3>& x, double t,
                                double spacing)
{
    double error2 = 0, norm2 = 0, layer_error2 = 0, layer_norm2 = 0, mode_dot = 0, mode_norm2 = 0;
    for (Eigen::Index a = 0; a < X.cols(); ++a) {
        const Vec3 Xa = X.col(a);
        const Vec3 u = x.col(a) - X.col(a);
        const Vec3 exact = cube.displacement(Xa, t);
        const Vec3 phi = cube.displacement(Xa, 0.0);
        const double e2 = (u - exact).squaredNorm();
        error2 += e2;
        norm2 += exact.squaredNorm();
        const double to_face = std::min(Xa.minCoeff(), (Vec3::Constant(cube.length) - Xa).minCoeff());
        if (to_face < spacing) {
            layer_error2 += e2;
            layer_norm2 += exact.squaredNorm();
        }
        mode_dot += u.dot(phi);
        mode_norm2 += phi.squaredNorm();
    }
    SwingingCubeError e;
    e.t = t;
    e.l2 = std::sqrt(error2 / norm2);
    e.boundary_layer = layer_norm2 > 0 ? std::sqrt(layer_error2 / layer_norm2) : 0.0;
    e.interior = norm2 > layer_norm2 ? std::sqrt((error2 - layer_error2) / (norm2 - layer_norm2)) : 0.0;
    e.mode_amplitude = mode_dot / mode_norm2;
    double residual2 = 0;
    for (Eigen::Index a = 0; a < X.cols(); ++a) {
        const Vec3 Xa = X.col(a);
        residual2 +=
            (Vec3(x.col(a) - X.col(a)) - e.mode_amplitude * cube.displacement(Xa, 0.0)).squaredNorm();
    }
    e.residual = std::sqrt(residual2 / mode_norm2);
    return e;
}

// The bound on the displacement of a stable run (decision swinging-blow-up). Without damping the leapfrog run
// conserves energy, and the swinging mode of eq. (53) is the cube's lowest (every mode of these walls has all
// three wave numbers >= pi/(2L), the swinging mode exactly these, and shear is slower than compression), so
// the mass-weighted displacement norm stays at most sqrt(phi^T K phi / phi^T M phi) / omega_min times its
// initial value, near 1. An instability grows past any such bound; near incompressibility the neo-Hookean law
// can saturate it before any J <= 0 (nu = 0.499 at 1.4 times the predicted step: 8 times the amplitude, and
// the run completed). 2 leaves a factor 4 for the sampled mode's Rayleigh quotient above omega_min^2.
constexpr double stable_displacement_bound = 2.0;

// sqrt(sum_a m_a |x_a - X_a|^2) [kg^1/2 m].
double mass_weighted_displacement(const std::vector<double>& mass, const Points<3>& X, const Points<3>& x)
{
    double sum = 0;
    for (Eigen::Index a = 0; a < X.cols(); ++a)
        sum += mass[static_cast<std::size_t>(a)] * (x.col(a) - X.col(a)).squaredNorm();
    return std::sqrt(sum);
}

// Stops an unstable run (exit 3) once its displacement exceeds the bound of a stable one, naming dt and the
// predicted limit.
void check_bounded_displacement(const Model& model, const Points<3>& X, double initial_displacement,
                                const Leapfrog& integrator)
{
    const double ratio =
        mass_weighted_displacement(model.mass(), X, integrator.positions()) / initial_displacement;
    if (ratio <= stable_displacement_bound) return;
    const double limit = predicted_time_step_limit(model);
    std::ostringstream m;
    m << "displacement " << ratio << " times its initial amplitude (bound " << stable_displacement_bound
      << " for a stable run, which conserves energy) at t = " << integrator.state().t
      << " s; time step dt = " << integrator.dt() << " s = " << integrator.dt() / limit
      << " times the predicted limit " << limit << " s";
    throw NumericalError(m.str(), integrator.state().step,
                         "time step above the stability limit (leapfrog instability): reduce cfl");
}

} // namespace

Points<3> swinging_cube_particles(const SwingingCubeSetup& setup)
{
    Rng rng(setup.seed);
    const int n = setup.per_side;
    return jittered_lattice(Vec3::Zero(), Vec3::Constant(setup.cube.length), {n, n, n}, setup.jitter, &rng);
}

Model swinging_cube_model(const SwingingCubeSetup& setup, const Points<3>& X)
{
    const double L = setup.cube.length;
    const Domain domain = box_domain(Vec3::Zero(), Vec3::Constant(L));
    BoundaryConditions bc;
    // Labels 0, 2, 4: X_i = 0 (symmetric); 1, 3, 5: X_i = L (antisymmetric); the prescribed components are
    // zero.
    bc.kind = {BoundaryKind::symmetric,     BoundaryKind::antisymmetric, BoundaryKind::symmetric,
               BoundaryKind::antisymmetric, BoundaryKind::symmetric,     BoundaryKind::antisymmetric};
    bc.displacement = [](int, const Vec3&, double) { return Vec3::Zero(); };
    return Model(build_reference_cells(X, domain, 2.0 * L / setup.per_side), domain, bc, setup.cube.material,
                 setup.options);
}

SwingingCubeResult run_swinging_cube(const SwingingCubeSetup& setup,
                                     const std::function<void(const SwingingCubeError&)>& observe,
                                     int samples, const StepObserver& on_step)
{
    const double spacing = setup.cube.length / setup.per_side;
    const Points<3> X = swinging_cube_particles(setup);
    const Model model = swinging_cube_model(setup, X);

    Points<3> x0 = X;
    for (Eigen::Index a = 0; a < X.cols(); ++a)
        x0.col(a) += setup.cube.displacement(X.col(a), 0.0);
    const long steps = static_cast<long>(std::ceil(
        setup.end_time / (setup.cfl * model.min_branch_length() / setup.cube.material.p_wave_speed())));
    const double dt = setup.end_time / static_cast<double>(steps);
    SwingingCubeResult r;
    r.initial_von_mises.reserve(static_cast<std::size_t>(X.cols()));
    double vm_error2 = 0, vm_norm2 = 0;
    for (const Mat3& F : model.deformation_gradients(x0, 0.0)) {
        const Eigen::Index a = static_cast<Eigen::Index>(r.initial_von_mises.size());
        const double vm = von_mises_stress(neo_hookean_cauchy_stress(F, setup.cube.material.lame()));
        const Mat3 F_exact = Mat3::Identity() + setup.cube.displacement_gradient(X.col(a), 0.0);
        const double vm_exact =
            von_mises_stress(neo_hookean_cauchy_stress(F_exact, setup.cube.material.lame()));
        r.initial_von_mises.push_back(vm);
        vm_error2 += (vm - vm_exact) * (vm - vm_exact);
        vm_norm2 += vm_exact * vm_exact;
    }
    r.initial_von_mises_error_l2 = std::sqrt(vm_error2 / vm_norm2);
    Leapfrog integrator(model, x0, Points<3>::Zero(3, X.cols()), dt, 0.0,
                        setup.time_step_check ? TimeStepCheck::refuse_above_limit : TimeStepCheck::off);
    const long stride = samples > 0 ? std::max(1L, steps / samples) : 0;
    if (observe) observe(measure_error(setup.cube, X, x0, 0.0, spacing));
    if (on_step) on_step(model, integrator);
    const double initial_displacement = mass_weighted_displacement(model.mass(), X, x0);
    for (long k = 1; k <= steps; ++k) {
        integrator.step();
        check_bounded_displacement(model, X, initial_displacement, integrator);
        if (on_step) on_step(model, integrator);
        if (observe && stride > 0 && (k % stride == 0 || k == steps))
            observe(measure_error(setup.cube, X, integrator.positions(), integrator.state().t, spacing));
    }

    r.X = X;
    r.error = measure_error(setup.cube, X, integrator.positions(), integrator.state().t, spacing);
    r.displacement_error_l2 = r.error.l2;
    r.spacing = spacing;
    r.dt = dt;
    r.dt_limit = predicted_time_step_limit(model);
    r.steps = steps;
    r.particles = static_cast<int>(X.cols());
    return r;
}

ModeErrorParts mode_error_parts(const SwingingCube& cube, const SwingingCubeError& error)
{
    const double cos_wt = std::cos(cube.angular_frequency() * error.t);
    return {std::abs(error.mode_amplitude - cos_wt) / std::abs(cos_wt), error.residual / std::abs(cos_wt)};
}

} // namespace softgrain::vsm
