#include "dpm/protocols/shear_modulus.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "dpm/analysis/stress.hpp"

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

ShearModulusResult shear_modulus(DpmSystem system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearedSystemObserver<DpmSystem>& observe)
{
    const ShearablePacking packing{
        [&system](Eigen::VectorXd& y, double tolerance) { return polish_newton(system, y, tolerance, 30); },
        [&system](Eigen::VectorXd& y, double dgamma_step) { shear_packing(system, y, dgamma_step); },
        [&system](const Eigen::VectorXd& y) {
            const Eigen::Matrix2d sigma = stress_tensor(system, y);
            return -0.5 * (sigma(0, 1) + sigma(1, 0)); // symmetric at equilibrium
        }};
    return shear_modulus(packing, std::move(x), dgamma, steps, force_tolerance, observing(system, observe));
}

ShearModulusResult shear_modulus(DpmSystem3d system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearedSystemObserver<DpmSystem3d>& observe,
                                 HessianStorage storage)
{
    const ShearablePacking packing{
        [&system, storage](Eigen::VectorXd& y, double tolerance) {
            return polish_newton3d(system, y, tolerance, 30, storage);
        },
        [&system](Eigen::VectorXd& y, double dgamma_step) { shear_packing3d(system, y, dgamma_step); },
        [&system](const Eigen::VectorXd& y) {
            const Eigen::Matrix3d sigma = stress_tensor3d(system, y);
            return -0.5 * (sigma(0, 1) + sigma(1, 0));
        }};
    return shear_modulus(packing, std::move(x), dgamma, steps, force_tolerance, observing(system, observe));
}

} // namespace softgrain::dpm
