// SPD section 6 (Trivino et al.): cohesive vertex-vertex links between adjacent cells of a tissue.
//
// A link joins vertex a of one cell to vertex b of the neighbouring cell at one end of their common
// interface; the other end of the interface carries the partner link (a', b'). The interface direction is the
// line through the two link midpoints, t = (m' - m)/|m' - m| with m = (x_a + x_b)/2, and n = +-perp(t) points
// from a to b (the sign fixed in the reference state, decision spd-tissue-link-frame). With d = x_b - x_a,
// the gap g = d.n and the slip tau = d.t:
//   u_n = g0 - g (inward, i.e. closing, positive),  u_t = tau - tau0,
//   f_n = k_n u_n,  f_t = k_t u_t  (section 6; compression and inward displacement positive),
//   W = k_n u_n^2 / 2 + k_t u_t^2 / 2  [J].
// Yield function, eq. (39): zeta = f_n/f_n^0 + |f_t/f_t^0|^alpha - 1 with f_n^0 < 0 (tensile threshold) and
// f_t^0 > 0; elastic while zeta < 0, broken for good once zeta >= 0. Units: SI (m, N, N/m).
// Valid for any rotation of the interface (W is invariant under rigid motions of the four vertices) as long
// as the link midpoints stay apart (|m' - m| > 0).
#pragma once

#include "core/vector.hpp"

#include <cmath>

namespace softgrain::spd {

// Parameters of the cohesive law: stiffnesses [N/m], thresholds [N] and the exponent alpha of eq. (39).
struct CohesiveLaw
{
    double k_n = 0, k_t = 0;
    double f_n0 = -1; // tensile normal threshold f_n^0 < 0 [N]
    double f_t0 = 1;  // tangential threshold f_t^0 > 0 at zero normal force [N]
    double alpha = 2; // the paper's choice (after Delenne et al. 2004)
};

// SPD eq. (39): zeta = f_n/f_n^0 + |f_t/f_t^0|^alpha - 1 (dimensionless); >= 0 breaks the link.
inline double yield_function(double f_n, double f_t, const CohesiveLaw& law)
{
    return f_n / law.f_n0 + std::pow(std::abs(f_t / law.f_t0), law.alpha) - 1.0;
}

// The zeta = 0 curve of eq. (39) solved for f_n: f_n = f_n^0 (1 - |f_t/f_t^0|^alpha) [N] (Fig. 31).
inline double yield_normal_force(double f_t, const CohesiveLaw& law)
{
    return law.f_n0 * (1.0 - std::pow(std::abs(f_t / law.f_t0), law.alpha));
}

// One link and its state. Vertices are global indices of the shell model.
struct CohesiveLink
{
    int a = 0, b = 0;                 // the linked vertices (a in one cell, b in the other)
    int partner_a = 0, partner_b = 0; // the link at the other end of the interface (it fixes the frame)
    double normal_sign = 1;           // n = normal_sign perp(t), so that n points from a to b at rest
    double gap0 = 0, slip0 = 0;       // g and tau in the reference state [m]
    bool broken = false;              // irreversible
    double f_n = 0, f_t = 0;          // forces of the last evaluation [N]
};

// Interface frame and link kinematics at the given positions.
struct LinkKinematics
{
    Vec2 d, t, n;             // x_b - x_a, unit interface tangent and normal (a -> b)
    double length = 0;        // |m' - m| [m]
    double gap = 0, slip = 0; // d.n, d.t [m]
};
inline LinkKinematics link_kinematics(const CohesiveLink& link, const Vec2& xa, const Vec2& xb,
                                      const Vec2& xpa, const Vec2& xpb)
{
    LinkKinematics k;
    k.d = xb - xa;
    const Vec2 m = 0.5 * ((xpa + xpb) - (xa + xb));
    k.length = m.norm();
    k.t = m / k.length;
    k.n = link.normal_sign * Vec2(-k.t.y(), k.t.x());
    k.gap = k.d.dot(k.n);
    k.slip = k.d.dot(k.t);
    return k;
}

// The link energy W(x_a, x_b, x_a', x_b') written once (templated for finite-difference and automatic
// differentiation checks) [J].
template <class Scalar>
Scalar link_energy(const CohesiveLink& link, const CohesiveLaw& law, const Eigen::Matrix<Scalar, 2, 1>& xa,
                   const Eigen::Matrix<Scalar, 2, 1>& xb, const Eigen::Matrix<Scalar, 2, 1>& xpa,
                   const Eigen::Matrix<Scalar, 2, 1>& xpb)
{
    using std::sqrt;
    const Eigen::Matrix<Scalar, 2, 1> d = xb - xa, m = Scalar(0.5) * ((xpa + xpb) - (xa + xb));
    const Scalar L = sqrt(m.squaredNorm());
    const Scalar tx = m.x() / L, ty = m.y() / L;
    const Scalar gap = link.normal_sign * (-ty * d.x() + tx * d.y());
    const Scalar slip = tx * d.x() + ty * d.y();
    const Scalar u_n = Scalar(link.gap0) - gap, u_t = slip - Scalar(link.slip0);
    return Scalar(0.5 * law.k_n) * u_n * u_n + Scalar(0.5 * law.k_t) * u_t * u_t;
}

// Forces -dW/dx on the four vertices [N] and the link forces f_n, f_t. With (the frame turns with m)
//   G = dW/dm = (f_n tau + f_t g) n / L,
//   F_b = f_n n - f_t t + G/2,  F_a = -f_n n + f_t t + G/2,  F_a' = F_b' = -G/2.
// They sum to zero (Newton's third law) and their moment vanishes (W is rotation invariant).
struct LinkForces
{
    double f_n = 0, f_t = 0;
    Vec2 a, b, partner_a, partner_b;
};
inline LinkForces link_forces(const CohesiveLink& link, const CohesiveLaw& law, const LinkKinematics& k)
{
    LinkForces F;
    F.f_n = law.k_n * (link.gap0 - k.gap);
    F.f_t = law.k_t * (k.slip - link.slip0);
    const Vec2 G = (F.f_n * k.slip + F.f_t * k.gap) / k.length * k.n;
    F.b = F.f_n * k.n - F.f_t * k.t + 0.5 * G;
    F.a = -F.f_n * k.n + F.f_t * k.t + 0.5 * G;
    F.partner_a = -0.5 * G;
    F.partner_b = -0.5 * G;
    return F;
}

} // namespace softgrain::spd
