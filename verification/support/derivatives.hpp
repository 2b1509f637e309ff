// Central-difference check of the gradient and Hessian of an energy, shared by the tests of the DPM energies.
//
// `energy(x, g, h)` returns the energy at x and adds its gradient to *g and its Hessian to *h when they are
// given (the convention of the DPM energy functions). The gradient is checked against central differences
// of the energy, the Hessian against central differences of the gradient. Steps of 1e-6 on O(1)
// coordinates: truncation h^2 |U'''| ~ 1e-12, round-off eps |U| / h ~ 1e-10; the allowed 1e-7 of the largest
// entry (or of 1) is far above both and far below the O(1) relative error of a wrong derivative. A random
// configuration has a Heaviside or region boundary within a step of a sample with probability ~1e-5.
#pragma once

#include "support/tolerance.hpp"

#include <Eigen/Core>

#include <algorithm>

namespace softgrain::verification {

template <class Energy>
void check_against_central_differences(const Energy& energy, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd& g, const Eigen::MatrixXd& h)
{
    const Eigen::Index dofs = x.size();
    const double step = 1e-6;
    Eigen::VectorXd g_fd(dofs);
    Eigen::MatrixXd h_fd(dofs, dofs);
    for (Eigen::Index k = 0; k < dofs; ++k) {
        Eigen::VectorXd xp = x, xm = x, gp = Eigen::VectorXd::Zero(dofs), gm = Eigen::VectorXd::Zero(dofs);
        xp(k) += step;
        xm(k) -= step;
        g_fd(k) = (energy(xp, &gp, nullptr) - energy(xm, &gm, nullptr)) / (2 * step);
        h_fd.col(k) = (gp - gm) / (2 * step);
    }
    const double g_scale = std::max(1.0, g.cwiseAbs().maxCoeff()),
                 h_scale = std::max(1.0, h.cwiseAbs().maxCoeff());
    CHECK_CLOSE((g - g_fd).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 1e-7 * g_scale}));
    CHECK_CLOSE((h - h_fd).cwiseAbs().maxCoeff(), 0.0, (Tolerance{0, 1e-7 * h_scale}));
}

} // namespace softgrain::verification
