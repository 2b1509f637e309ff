#include "vsm/patch_test.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/particle_layouts.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace softgrain::vsm {

Mat3 patch_displacement_gradient(double alpha)
{
    Mat3 M;
    M << 1, 2, 3, 4, 5, 6, 7, 8, 9;
    return alpha * M;
}

PatchResult run_patch_test(const PatchSetup& setup, const PatchObserver& observe)
{
    const Domain domain = box_domain(Vec3::Zero(), Vec3::Ones());
    Rng rng(setup.seed);
    const int n = setup.per_side;
    const Points<3> X = jittered_lattice(Vec3::Zero(), Vec3::Ones(), {n, n, n}, setup.jitter, &rng);
    const double h = 1.0 / n;
    const Mat3 G = patch_displacement_gradient(setup.alpha);
    const LameParameters lame = setup.material.lame();
    // Loads are ramped linearly, r(t) = min(t / ramp_time, 1); at every r the homogeneous state F = I + r G
    // is the exact solution, so the traction follows it: T = P(I + r G) N.
    const bool static_test = setup.variant == PatchVariant::A;
    const auto ramp = [&](double t) { return static_test ? 1.0 : std::min(t / setup.ramp_time, 1.0); };

    BoundaryConditions bc;
    bc.displacement = [&](int, const Vec3& W, double t) { return Vec3(ramp(t) * (G * W)); };
    if (setup.variant == PatchVariant::C) {
        bc.kind.assign(6, BoundaryKind::free);
        bc.kind[4] = BoundaryKind::total; // X3 = 0
        bc.traction = [&](int label, const Vec3&, double t) {
            const Vec3 normal = (label % 2 == 0 ? -1.0 : 1.0) * Vec3::Unit(label / 2);
            return Vec3(neo_hookean_stress(Mat3::Identity() + ramp(t) * G, lame) * normal);
        };
    } else {
        bc.kind.assign(6, BoundaryKind::total);
    }
    const Model model(build_reference_cells(X, domain, 2.0 * h), domain, bc, setup.material, setup.options);

    PatchResult result;
    result.X = X;
    result.particles = static_cast<int>(model.size());
    result.force_scale = setup.material.young * setup.alpha * h * h;
    const Points<3> exact = X + G * X;
    const auto max_column_norm = [](const Points<3>& p) { return p.colwise().norm().maxCoeff(); };
    if (static_test) {
        result.max_error = max_column_norm(model.forces(exact, 0.0));
        if (observe) observe({model, exact, Points<3>::Zero(3, X.cols()), 0.0, 0, 1.0, true});
        return result;
    }
    const double dt = setup.cfl * model.min_branch_length() / setup.material.p_wave_speed();
    Leapfrog integrator(model, X, Points<3>::Zero(3, X.cols()), dt, setup.damping,
                        setup.time_step_check ? TimeStepCheck::refuse_above_limit : TimeStepCheck::off);
    const long steps = static_cast<long>(std::ceil((setup.ramp_time + setup.hold_time) / dt));
    const auto state = [&](bool final) {
        const double t = integrator.state().t;
        observe({model, integrator.positions(), integrator.half_step_velocities(), t, integrator.state().step,
                 ramp(t), final});
    };
    if (observe) state(false);
    for (long k = 0; k < steps; ++k) {
        integrator.step();
        if (observe) state(k + 1 == steps);
    }
    const Points<3> x = integrator.positions();
    result.max_error = max_column_norm(x - exact);
    result.final_residual = max_column_norm(model.forces(x, integrator.state().t));
    result.steps = steps;
    result.dt = dt;
    return result;
}

double patch_relative_error(const PatchSetup& setup, const PatchResult& result)
{
    if (setup.variant == PatchVariant::A) {
        if (!(result.force_scale > 0 && std::isfinite(result.force_scale)))
            throw NumericalError(
                "patch test A: the force scale E alpha h^2 = " + std::to_string(result.force_scale) +
                    " N is not a positive finite number",
                0, "E or alpha so small or large that the particle forces under- or overflow");
        return result.max_error / result.force_scale;
    }
    return result.max_error / patch_displacement_gradient(setup.alpha).rowwise().sum().norm();
}

} // namespace softgrain::vsm
