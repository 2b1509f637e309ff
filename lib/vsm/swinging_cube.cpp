#include "vsm/swinging_cube.hpp"

#include "core/rng.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/particle_layouts.hpp"

#include <cmath>
#include <numbers>

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

SwingingCubeResult run_swinging_cube(const SwingingCubeSetup& s)
{
    const double L = s.cube.length;
    const Domain domain = box_domain(Vec3::Zero(), Vec3::Constant(L));
    Rng rng(s.seed);
    const int n = s.per_side;
    const Points<3> X = jittered_lattice(Vec3::Zero(), Vec3::Constant(L), {n, n, n}, s.jitter, &rng);
    BoundaryConditions bc;
    // Labels 0, 2, 4: X_i = 0 (symmetric); 1, 3, 5: X_i = L (antisymmetric); the prescribed components are
    // zero.
    bc.kind = {BoundaryKind::symmetric,     BoundaryKind::antisymmetric, BoundaryKind::symmetric,
               BoundaryKind::antisymmetric, BoundaryKind::symmetric,     BoundaryKind::antisymmetric};
    bc.displacement = [](int, const Vec3&, double) { return Vec3::Zero(); };
    const Model model(build_reference_cells(X, domain, 2.0 * L / n), domain, bc, s.cube.material, s.options);

    Points<3> x0 = X;
    for (Eigen::Index a = 0; a < X.cols(); ++a)
        x0.col(a) += s.cube.displacement(X.col(a), 0.0);
    const long steps = static_cast<long>(
        std::ceil(s.end_time / (s.cfl * model.min_branch_length() / s.cube.material.p_wave_speed())));
    const double dt = s.end_time / static_cast<double>(steps);
    Leapfrog integrator(model, x0, Points<3>::Zero(3, X.cols()), dt, 0.0);
    for (long k = 0; k < steps; ++k)
        integrator.step();

    const Points<3> x = integrator.positions();
    const double t = integrator.state().t;
    double error2 = 0, norm2 = 0;
    for (Eigen::Index a = 0; a < X.cols(); ++a) {
        const Vec3 exact = s.cube.displacement(X.col(a), t);
        error2 += (Vec3(x.col(a) - X.col(a)) - exact).squaredNorm();
        norm2 += exact.squaredNorm();
    }
    SwingingCubeResult r;
    r.displacement_error_l2 = std::sqrt(error2 / norm2);
    r.spacing = L / n;
    r.dt = dt;
    r.steps = steps;
    r.particles = static_cast<int>(X.cols());
    return r;
}

} // namespace softgrain::vsm
