// SPD force laws as pure functions (Trivino et al., sections 2.2-2.4):
//
//   X <- clamp(X + dX, -P, P)                          elastic-perfectly plastic update, eq. (2)
//   dF = k_s dc,  dM = k_b dtheta  (with eq. (2))      stretch (dc: contraction) and hinge, eqs. (1), (3)
//   f_n = k_n max(0, (r_i + r_j) - distance)           normal contact, eq. (6)
//   f_t <- clamp(f_t - k_t du_t, -mu f_n, mu f_n)      Coulomb friction, eq. (7)
//   |F| = M/l_(k-1,k), M/l_(k,k+1) normal to elements  torque as two couples, eqs. (8)-(9)
//   w_k = (l - a)/l,  w_(k+1) = a/l                    force on an element to its end vertices, Fig. 5
//
// Sign: compression, contraction and overlap counted positive (section 2.2); angles and torques
// counter-clockwise positive. Units: SI, forces [N], torques [N m], lengths [m], k_s, k_n, k_t [N/m],
// k_b [N m/rad]. Deliberate departures from the text (the clamp of eq. (2), the sign of eq. (6), the
// magnitude of eq. (8)) are described at each function with their decisions.
// Valid for thresholds P >= 0 and mu f_n >= 0 (std::clamp needs -P <= P), elements of non-zero length,
// 0 <= a <= l, and increments small enough that an element turns by less than pi between two
// evaluations (rotations are read in (-pi, pi]).
#pragma once

#include "core/vector.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace softgrain::spd {

// SPD eq. (2), the elastic-perfectly plastic update of an internal variable X (a force or a torque) by an
// elastic trial increment dX with threshold P: X + dX while |X + dX| < P. Beyond it the paper sets the
// increment to 0; softgrain returns X + dX clamped to [-P, P] (return mapping, decision spd-eq2-clamp):
// identical for increments that do not cross P, and the threshold is reached instead of approached.
// Returns the new X. P may be infinite (elastic).
inline double elastoplastic_update(double X, double dX, double P)
{
    return std::clamp(X + dX, -P, P);
}

// SPD eqs. (1) and (3) are eq. (2) applied to dF = k_s * (contraction increment) and dM = k_b * dtheta.

// SPD eqs. (8)-(9) (the second is printed as a duplicate "(8)"): a torque M at vertex k (turning angle
// theta_k between elements (k-1,k) and (k,k+1), counter-clockwise positive) replaced by two couples of
// forces perpendicular to the elements. softgrain uses magnitudes M/l_(k-1,k) and M/l_(k,k+1), i.e. the
// forces -M d(theta_k)/dx of the hinge energy (decision spd-couples-magnitude): each couple has moment M,
// the two are of opposite senses, so the net force and the net moment vanish and the virtual work is
// -M dtheta. Returns the forces on vertices k-1, k, k+1 [N] for M [N m].
struct ThreeForces
{
    Vec2 previous, centre, next;
};
// The same from the element vectors e1 = x - x_prev, e2 = x_next - x and their squared lengths (a caller
// that has them from the stretch law passes them on).
inline ThreeForces edge_couples(const Vec2& e1, double e1_squared, const Vec2& e2, double e2_squared,
                                double M)
{
    const Vec2 g1 = Vec2(-e1.y(), e1.x()) / e1_squared; // d(direction angle of e1)/d(e1)
    const Vec2 g2 = Vec2(-e2.y(), e2.x()) / e2_squared;
    // theta = angle(e2) - angle(e1): dtheta/dx_prev = g1, dtheta/dx = -g1 - g2, dtheta/dx_next = g2.
    return {-M * g1, M * (g1 + g2), -M * g2};
}
inline ThreeForces torque_to_couples(const Vec2& x_prev, const Vec2& x, const Vec2& x_next, double M)
{
    const Vec2 e1 = x - x_prev, e2 = x_next - x;
    return edge_couples(e1, e1.squaredNorm(), e2, e2.squaredNorm(), M);
}

// Turning angle at x between the elements (x_prev, x) and (x, x_next), in (-pi, pi], CCW positive.
inline double turning_angle(const Vec2& x_prev, const Vec2& x, const Vec2& x_next)
{
    const Vec2 e1 = x - x_prev, e2 = x_next - x;
    return std::atan2(cross2(e1, e2), e1.dot(e2));
}

// Rotation of an element vector from `before` to `after`, in (-pi, pi], CCW positive: atan2(y, x) with
// y = before x after, x = before . after. Within a time step an element turns by far less than 0.01 rad: for
// x > 0 and |y| < 0.01 x the series atan(t) = t - t^3/3 + t^5/5 - t^7/7 (t = y/x) is exact to round-off
// (the first term left out, t^9/9, is below 1.2e-17 t; verification/spd/force_laws.cpp) at a fraction of
// the cost of atan2; std::atan2 otherwise.
inline double element_rotation(const Vec2& before, const Vec2& after)
{
    const double y = cross2(before, after), x = before.dot(after);
    if (x > 0 && std::abs(y) < 0.01 * x) {
        const double t = y / x, t2 = t * t;
        return t * (1 - t2 * (1.0 / 3 - t2 * (0.2 - t2 / 7)));
    }
    return std::atan2(y, x);
}

// Fig. 5: a force acting on an element of length l at a distance a from its end k is shared by the end
// vertices with weights w_k = (l - a)/l and w_(k+1) = a/l (lever rule: force and moment conserved).
inline std::array<double, 2> transfer_weights(double a, double l)
{
    return {(l - a) / l, a / l};
}

// SPD eq. (6) with the overlap read as positive when the sphero-objects interpenetrate (decision
// spd-eq6-sign): f_n = k_n max(0, (r_i + r_j) - distance) [N], repulsive.
inline double normal_contact_force(double k_n, double distance, double radius_sum)
{
    return k_n * std::max(0.0, radius_sum - distance);
}

// SPD eq. (7), incremental Coulomb friction: f_t <- clamp(f_t - k_t du_t, -mu f_n, mu f_n) (eq. (2) read as
// a return mapping). du_t is the tangential displacement increment of the vertex relative to the element
// at the contact point [m]; f_t is the tangential force on the vertex [N]. The contact record keeps f_t.
inline double coulomb_friction_update(double f_t, double k_t, double du_t, double mu, double f_n)
{
    return elastoplastic_update(f_t, -k_t * du_t, mu * f_n);
}

} // namespace softgrain::spd
