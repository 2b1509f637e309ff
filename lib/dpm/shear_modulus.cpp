#include "dpm/shear_modulus.hpp"

#include "core/errors.hpp"
#include "dpm/modes.hpp"
#include "dpm/stress.hpp"

#include <gsl/gsl_fit.h>

#include <sstream>
#include <string>

namespace softgrain::dpm {

ShearModulusResult shear_modulus(DpmSystem system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance)
{
    ShearModulusResult out;
    std::vector<double> strain;
    const auto minimise = [&](int step) {
        out.force_max = polish_newton(system, x, force_tolerance, 30);
        if (!(out.force_max < force_tolerance)) {
            std::ostringstream what;
            what << "Newton minimisation after a shear step (largest force " << out.force_max << ")";
            throw NumericalError(
                what.str(), step,
                "the packing is not at a minimum (a saddle or a soft direction Newton cannot fix)");
        }
    };
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) shear_packing(system, x, dgamma);
        minimise(step);
        strain.push_back(step * dgamma);
        const Eigen::Matrix2d sigma = stress_tensor(system, x);
        out.shear_stress.push_back(-0.5 * (sigma(0, 1) + sigma(1, 0))); // symmetric at equilibrium
    }
    double c0 = 0, c00 = 0, c01 = 0, c11 = 0, sumsq = 0;
    gsl_fit_linear(strain.data(), 1, out.shear_stress.data(), 1, strain.size(), &c0, &out.modulus, &c00, &c01,
                   &c11, &sumsq);
    return out;
}

} // namespace softgrain::dpm
