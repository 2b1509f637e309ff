// Pairwise contact (stabilisation) energy of VSM (Frenning 2022, eqs. (49)-(50), sections 2.6 and 4).
//
//   U_ab = 1/2 K^n |u^n|^2 + 1/2 K^t |u^t|^2 = 1/2 K^t |u|^2 + 1/2 (K^n - K^t) (u.n)^2     (49)
//   K^n = xi_n E A_ab / L_ab,  K^t = xi_t G A_ab / L_ab                                    (50)
//
// u = x~_ab - y~_ab the local (non-affine) bond displacement, eqs. (29)-(30), u^n = (u.n) n, u^t = u - u^n;
// A_ab the reference face area, L_ab = |X_ab| the reference branch length, G = mu. The normal direction n
// is x~_ab / |x~_ab| for two real particles (so U depends on x~ also through n) and the fixed boundary
// normal for a ghost.
// Sign: U >= 0; the functions return gradients dU/d(.), the forces are their negatives. The bond resists
// opening and closing alike (no tension cut-off, it never breaks).
// Units: E, G [Pa], A_ab [m^2], L_ab and u [m], K [N/m]; energies in J, gradients in N.
// Valid for xi_n, xi_t >= 0, |x~_ab| > 0 for a real pair (n is undefined when the two particles coincide)
// and a unit boundary normal for a ghost.
#pragma once

#include "core/vector.hpp"

namespace softgrain::vsm {

struct ContactStiffness
{
    double normal = 0;     // K^n, eq. (50a)
    double tangential = 0; // K^t, eq. (50b)
};

inline ContactStiffness contact_stiffness(double xi_n, double xi_t, double E, double G, double area,
                                          double length)
{
    return {xi_n * E * area / length, xi_t * G * area / length};
}

// U = 1/2 K^t |u|^2 + 1/2 (K^n - K^t)(u.n)^2, eq. (49).
inline double contact_energy(const Vec3& u, const Vec3& n, const ContactStiffness& k)
{
    const double un = u.dot(n);
    return 0.5 * k.tangential * u.squaredNorm() + 0.5 * (k.normal - k.tangential) * un * un;
}

// dU/dy~ = -(K^t u + (K^n - K^t)(u.n) n) at fixed n.
inline Vec3 contact_gradient_y(const Vec3& u, const Vec3& n, const ContactStiffness& k)
{
    return -(k.tangential * u + (k.normal - k.tangential) * u.dot(n) * n);
}

// dU/dx~ for a real pair, n = x~/|x~|: -dU/dy~ + (K^n - K^t)(u.n)(I - n n) u / |x~|.
inline Vec3 contact_gradient_x_real(const Vec3& u, const Vec3& x_tilde, const ContactStiffness& k)
{
    const double length = x_tilde.norm();
    const Vec3 n = x_tilde / length;
    const double un = u.dot(n);
    return -contact_gradient_y(u, n, k) + (k.normal - k.tangential) * un * (u - un * n) / length;
}

} // namespace softgrain::vsm
