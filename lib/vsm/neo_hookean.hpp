// Neo-Hookean mean stress of VSM (Frenning 2022, eq. (48), section 4).
//
//   U(F) = (lambda/2)(ln J)^2 - mu ln J + (mu/2)(tr C - 3),  C = F^T F,  J = det F     (48)
//   P(F) = dU/dF = mu (F - F^-T) + lambda ln J F^-T
//
// U: strain energy per reference volume [J/m^3 = Pa]; P: first Piola-Kirchhoff (nominal) stress [Pa];
// lambda, mu: Lame parameters [Pa]. Sign: tension positive (P N is the traction on a reference face of
// outward normal N); U = 0 and P = 0 at F = I.
// Valid for J > 0 only; callers check J and report J <= 0 as a numerical failure (the particle is inverted).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>

namespace softgrain::vsm {

using Mat3 = Eigen::Matrix3d;

struct LameParameters
{
    double lambda = 0; // Pa
    double mu = 0;     // Pa, shear modulus G
};

// Standard conversion from Young's modulus E [Pa] and Poisson's ratio nu (-1 < nu < 1/2).
inline LameParameters lame_from_young(double E, double nu)
{
    return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

inline double neo_hookean_energy(const Mat3& F, const LameParameters& m)
{
    const double log_J = std::log(F.determinant());
    return 0.5 * m.lambda * log_J * log_J - m.mu * log_J + 0.5 * m.mu * ((F.transpose() * F).trace() - 3.0);
}

inline Mat3 neo_hookean_stress(const Mat3& F, const LameParameters& m)
{
    const Mat3 F_inv_T = F.inverse().transpose();
    return m.mu * (F - F_inv_T) + m.lambda * std::log(F.determinant()) * F_inv_T;
}

// Cauchy stress sigma = P F^T / J of the neo-Hookean material [Pa] (valid for J > 0).
inline Mat3 neo_hookean_cauchy_stress(const Mat3& F, const LameParameters& m)
{
    return neo_hookean_stress(F, m) * F.transpose() / F.determinant();
}

// Von Mises equivalent stress sqrt(3/2 s : s), s = sigma - tr(sigma) I / 3 the deviator [Pa].
inline double von_mises_stress(const Mat3& sigma)
{
    const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    return std::sqrt(1.5 * s.cwiseProduct(s).sum());
}

} // namespace softgrain::vsm
