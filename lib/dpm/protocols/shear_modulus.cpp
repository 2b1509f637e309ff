#include "dpm/protocols/shear_modulus.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <sstream>
#include <string>

namespace softgrain::dpm {

ShearModulusResult shear_modulus(const ShearablePacking& packing, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearStepObserver& observe)
{
    ShearModulusResult out;
    std::vector<double> strain;
    const auto minimise = [&](int step) {
        out.force_max = packing.minimise(x, force_tolerance);
        if (!(out.force_max < force_tolerance) && packing.relax) { // Newton crawls: FIRE first (header)
            packing.relax(x, 1e-3 * force_tolerance);
            out.force_max = packing.minimise(x, 1e-4 * force_tolerance);
        }
        if (!(out.force_max < force_tolerance)) {
            std::ostringstream what;
            what << "Newton minimisation after a shear step (largest force " << out.force_max << ")";
            throw NumericalError(
                what.str(), step,
                "the packing is not at a minimum (a saddle or a soft direction Newton cannot fix)");
        }
    };
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) packing.shear(x, dgamma);
        minimise(step);
        if (step == 0) out.equilibrium = x;
        strain.push_back(step * dgamma);
        out.shear_stress.push_back(packing.stress(x));
        if (observe) observe(step, x, out.shear_stress.back());
    }
    out.modulus = fit_line(strain, out.shear_stress).value().slope; // steps >= 1: two points at least
    return out;
}

// The observer of a system's shear: the system as sheared so far, or none.
template <class System>
ShearStepObserver observing(const System& system, const ShearedSystemObserver<System>& observe)
{
    if (!observe) return {};
    return [&system, &observe](int step, const Eigen::VectorXd& y, double stress) {
        observe(step, system, y, stress);
    };
}

// FIRE from y to an rms force below `tolerance` with the settings `fire` (the fallback of shear_modulus);
// empty without settings. NumericalError if FIRE does not converge.
template <class System>
std::function<void(Eigen::VectorXd&, double)> fire_fallback(const System& system,
                                                            const std::optional<FireOptions>& fire)
{
    if (!fire) return {};
    return [&system, fire](Eigen::VectorXd& y, double tolerance) {
        RelaxOptions options{Relaxation::fire, *fire};
        options.fire.force_tolerance = tolerance;
        const RelaxResult r = relax(system, y, options);
        if (!r.converged)
            throw NumericalError("FIRE before the Newton minimisation of a shear step (" +
                                     relax_shortfall(r, options) + ")",
                                 0, "the packing is not at a minimum");
    };
}

ShearModulusResult shear_modulus(DpmSystem system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearedSystemObserver<DpmSystem>& observe,
                                 const std::optional<FireOptions>& fire)
{
    const ShearablePacking packing{
        [&system](Eigen::VectorXd& y, double tolerance) { return polish_newton(system, y, tolerance, 30); },
        [&system](Eigen::VectorXd& y, double dgamma_step) { shear_packing(system, y, dgamma_step); },
        [&system](const Eigen::VectorXd& y) {
            const Eigen::Matrix2d sigma = stress_tensor(system, y);
            return -0.5 * (sigma(0, 1) + sigma(1, 0)); // symmetric at equilibrium
        },
        fire_fallback(system, fire)};
    return shear_modulus(packing, std::move(x), dgamma, steps, force_tolerance, observing(system, observe));
}

ShearModulusResult shear_modulus(DpmSystem3d system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearedSystemObserver<DpmSystem3d>& observe,
                                 HessianStorage storage, const std::optional<FireOptions>& fire)
{
    const ShearablePacking packing{
        [&system, storage](Eigen::VectorXd& y, double tolerance) {
            return polish_newton3d(system, y, tolerance, 30, storage);
        },
        [&system](Eigen::VectorXd& y, double dgamma_step) { shear_packing3d(system, y, dgamma_step); },
        [&system](const Eigen::VectorXd& y) {
            const Eigen::Matrix3d sigma = stress_tensor3d(system, y);
            return -0.5 * (sigma(0, 1) + sigma(1, 0));
        },
        fire_fallback(system, fire)};
    return shear_modulus(packing, std::move(x), dgamma, steps, force_tolerance, observing(system, observe));
}

} // namespace softgrain::dpm
