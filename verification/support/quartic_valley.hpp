// A two-dimensional energy whose saddles and minima are known in closed form, for the saddle tests of the
// jamming protocols (verification/dpm/protocols/saddle.cpp, verification/dpm/analysis/packing_hessian3d.cpp):
// U = c + a2/2 x^2 + a4/4 x^4 + 1/2 y^2 with its exact gradient and Hessian. a2 < 0 < a4: a saddle at the
// origin between minima at x = +-sqrt(-a2/a4); a2 > 0: a minimum at the origin.
#pragma once

#include "dpm/analysis/modes.hpp"

namespace softgrain::verification {

inline dpm::EnergyWithDerivatives quartic_valley(double c, double a2, double a4)
{
    return [=](const Eigen::VectorXd& r, Eigen::VectorXd* g, Eigen::MatrixXd* h) {
        const double x = r(0), y = r(1);
        if (g) *g += Eigen::Vector2d(a2 * x + a4 * x * x * x, y);
        if (h) *h += Eigen::Vector2d(a2 + 3 * a4 * x * x, 1.0).asDiagonal().toDenseMatrix();
        return c + 0.5 * a2 * x * x + 0.25 * a4 * x * x * x * x + 0.5 * y * y;
    };
}

} // namespace softgrain::verification
