// SPD section 2 force laws as units: eqs. (1)-(3) hysteresis, element rotations, eqs. (8)-(9) couples, Fig. 5
// force transfer, section 2.3 sphero-segment contact, eq. (7) Coulomb friction, eqs. (10)-(13) calibration
// round trip.
#include "spd/force_laws.hpp"
#include "core/geometry.hpp"
#include "spd/calibration.hpp"
#include "spd/shell_model.hpp"
#include "spd/time_step_limits.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>
#include <vector>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

TEST_CASE("elastic-perfectly plastic increments trace the hysteresis loop [SPD eqs. (1)-(2)]")
{
    // Strain-driven cycle 0 -> +3 -> -3 -> +3 (in units of the yield displacement) with k = 2, P = 2:
    // the force follows k u until |F| = P, stays at +-P while loading further, unloads elastically with
    // slope k, and the loop closes: after the full cycle F equals its value at the end of the first loading.
    const double k = 2.0, P = 2.0, du = 1e-3;
    double F = 0, u = 0;
    const auto drive = [&](double target) {
        while (std::abs(target - u) > du / 2) {
            const double step = target > u ? du : -du;
            F = elastoplastic_update(F, k * step, P);
            u += step;
        }
    };
    drive(0.5);
    CHECK_CLOSE(F, 1.0, (Tolerance{0, 1e3 * round_off})); // elastic branch F = k u
    drive(3.0);
    CHECK_CLOSE(F, P, (Tolerance{0, 0})); // perfectly plastic plateau, exactly at the threshold
    drive(2.0);
    CHECK_CLOSE(F, P - k * 1.0, (Tolerance{0, 1e3 * round_off})); // elastic unloading, slope k
    drive(-3.0);
    CHECK_CLOSE(F, -P, (Tolerance{0, 0}));
    drive(3.0);
    CHECK_CLOSE(F, P, (Tolerance{0, 0}));
    // Residual (plastic) displacement after unloading to F = 0 from the plateau: u_p = 3 - P/k = 2.
    while (F > 0) {
        F = elastoplastic_update(F, -k * du, P);
        u -= du;
    }
    CHECK_CLOSE(u, 3.0 - P / k, (Tolerance{0, du}));
}

TEST_CASE("torque as two couples: zero net force and moment, each couple of moment M, work -M dtheta [SPD "
          "eqs. (8)-(9)]")
{
    const Vec2 a(-1.0, 0.2), x(0.1, 0.0), b(0.9, 0.7);
    const double M = 0.37;
    const ThreeForces f = torque_to_couples(a, x, b, M);
    const Vec2 net = f.previous + f.centre + f.next;
    CHECK_CLOSE(net.norm(), 0.0, (Tolerance{0, 10 * round_off}));
    const double moment = cross2(a, f.previous) + cross2(x, f.centre) + cross2(b, f.next);
    CHECK_CLOSE(moment, 0.0, (Tolerance{0, 10 * round_off}));
    // Forces perpendicular to the elements, magnitude M / l on the outer vertices.
    CHECK_CLOSE(f.previous.dot(x - a), 0.0, (Tolerance{0, 10 * round_off}));
    CHECK_CLOSE(f.next.dot(b - x), 0.0, (Tolerance{0, 10 * round_off}));
    CHECK_CLOSE(f.previous.norm(), M / (x - a).norm(), (Tolerance{10 * round_off, 0}));
    CHECK_CLOSE(f.next.norm(), M / (b - x).norm(), (Tolerance{10 * round_off, 0}));
    // Moment of the couple on element (k-1,k) about vertex k: the force on k-1 times l_(k-1,k) = +M (it turns
    // that element counter-clockwise, reducing theta for M > 0); the couple on (k,k+1) has moment -M.
    CHECK_CLOSE(cross2(Vec2(a - x), f.previous), M, (Tolerance{10 * round_off, 0}));
    CHECK_CLOSE(cross2(Vec2(b - x), f.next), -M, (Tolerance{10 * round_off, 0}));
    // Virtual work: sum f . dx = -M dtheta for any small displacement (central difference, O(h^2) ~ 1e-12).
    const Vec2 da(0.3, -0.2), dx(-0.1, 0.4), db(0.25, 0.05);
    const double h = 1e-6;
    const double dtheta = (turning_angle(a + h * da, x + h * dx, b + h * db) -
                           turning_angle(a - h * da, x - h * dx, b - h * db)) /
                          (2 * h);
    CHECK_CLOSE(f.previous.dot(da) + f.centre.dot(dx) + f.next.dot(db), -M * dtheta, (Tolerance{1e-8, 0}));
}

TEST_CASE(
    "the rotation of an element in a step: the atan series agrees with atan2 to round-off [SPD eq. (3)]")
{
    // element_rotation uses t - t^3/3 + t^5/5 - t^7/7 (t = tan of the rotation) below |t| = 0.01; the first
    // term left out is t^9/9 < 1.2e-17 |t| there, so the series and atan2 differ by round-off: a few ulps
    // (4 eps relative). Angles from 1e-12 rad up to 0.05 rad cross the switch to atan2; elements of
    // different lengths and orientations, both senses.
    for (const double length : {1e-3, 1.0, 7.3})
        for (const double direction : {0.0, 0.4, 2.9, -1.7})
            for (double angle = 1e-12; angle < 0.05; angle *= 1.37)
                for (const double sense : {1.0, -1.0}) {
                    const double turn = sense * angle;
                    const Vec2 before = length * Vec2(std::cos(direction), std::sin(direction));
                    const Vec2 after =
                        1.1 * length * Vec2(std::cos(direction + turn), std::sin(direction + turn));
                    const double exact = std::atan2(cross2(before, after), before.dot(after));
                    CHECK_CLOSE(element_rotation(before, after), exact, (Tolerance{4 * round_off, 0}));
                    CHECK_CLOSE(element_rotation(before, after), turn, (Tolerance{1e-9, 1e-15}));
                }
    // Large rotations (atan2 itself), including a half turn.
    CHECK_CLOSE(element_rotation(Vec2(1, 0), Vec2(-1, 1e-300)), std::numbers::pi, (Tolerance{round_off, 0}));
    CHECK_CLOSE(element_rotation(Vec2(1, 0), Vec2(0, -2)), -std::numbers::pi / 2, (Tolerance{round_off, 0}));
}

TEST_CASE("force transfer to element ends conserves force and moment [SPD Fig. 5]")
{
    const Vec2 A(0.0, 0.0), B(2.0, 1.0), f(0.3, -1.1);
    const double l = (B - A).norm();
    for (double a : {0.0, 0.4, 1.3, l}) {
        const auto w = transfer_weights(a, l);
        const Vec2 point = A + a * (B - A) / l;
        CHECK_CLOSE(w[0] + w[1], 1.0, (Tolerance{0, 4 * round_off}));
        // Moment about the contact point of the two end forces vanishes.
        CHECK_CLOSE(cross2(Vec2(A - point), Vec2(w[0] * f)) + cross2(Vec2(B - point), Vec2(w[1] * f)), 0.0,
                    (Tolerance{0, 20 * round_off}));
    }
}

TEST_CASE(
    "sphero-segment contact force is continuous across the three cases of section 2.3 [SPD eq. (6), Fig. 4]")
{
    // A vertex of radius r slides along a horizontal line just inside the reach of a sphero-segment AB;
    // the overlap and the force vary continuously through a = 0 and a = l.
    const Vec2 A(0.0, 0.0), B(1.0, 0.0);
    const double reach = 0.2, k_n = 10.0;
    double previous = -1;
    for (double x = -0.1; x <= 1.1; x += 1e-4) {
        const Vec2 c(x, 0.15);
        const SegmentProximity p = point_segment_proximity(c, A, B);
        const double fn = normal_contact_force(k_n, p.distance, reach);
        if (previous >= 0) CHECK(std::abs(fn - previous) < 1e-3 * k_n * reach);
        previous = fn;
    }
    // In the interior branch the overlap is reach - 0.15 exactly.
    CHECK_CLOSE(normal_contact_force(k_n, point_segment_proximity(Vec2(0.5, 0.15), A, B).distance, reach),
                k_n * 0.05, (Tolerance{1e-12, 0}));
    CHECK(normal_contact_force(k_n, 0.25, reach) == 0.0);
}

namespace {
// A single mass point resting on a rigid wall under its weight m g, pulled sideways by T; returns its
// horizontal velocity after `time` (the sliding acceleration is (T - mu m g)/m once it slides).
double block_velocity(double T_over_mu_mg, double time)
{
    const double m = 1.0, g = 10.0, mu = 0.5, k = 1e4;
    ShellModel model;
    Shell wall;
    wall.closed = false;
    wall.rigid = true;
    Points<2> w(2, 2);
    w << -100.0, 100.0, 0.0, 0.0;
    model.add_shell(w, wall, 1.0);
    Shell block;
    block.closed = false;
    block.radius = 0.1;
    Points<2> c(2, 1);
    c << 0.0, 0.1 - m * g / k; // at its static overlap
    model.add_shell(c, block, m);
    model.set_contact_law({k, k, mu});
    model.set_applied_force(2, Vec2(T_over_mu_mg * mu * m * g, -m * g));
    const double dt = 0.05 * critical_time_step(model);
    for (double t = 0; t < time; t += dt)
        model.step(dt, 0.0);
    return model.velocity(2).x();
}
} // namespace

TEST_CASE("a block on a plane slides exactly when the tangential load exceeds mu f_n [SPD eq. (7)]")
{
    const double mu_g = 0.5 * 10.0, time = 2.0;
    // Below the threshold the block sticks: its velocity only oscillates in the tangential spring,
    // amplitude T/sqrt(k m) = 0.9 * 5 / 100 = 0.045 m/s at most.
    CHECK(block_velocity(0.9, time) < 0.05);
    // Above it, it sticks until the tangential spring reaches mu f_n (x = (T/k)(1 - cos w t), w = sqrt(k/m),
    // so cos w t_s = 1 - mu f_n/T) and then slides with acceleration (T - mu f_n)/m:
    // v = (T/(m w)) sin(w t_s) + (T - mu f_n)/m (time - t_s). Velocity Verlet at w dt = 0.05 and the onset of
    // sliding resolved to one step (dt (T - mu f_n)/m = 2.5e-4 m/s) give a 1e-3 relative tolerance.
    const double T = 1.1 * mu_g, w = 100.0;
    const double t_s = std::acos(1.0 - mu_g / T) / w;
    CHECK_CLOSE(block_velocity(1.1, time), T / w * std::sin(w * t_s) + (T - mu_g) * (time - t_s),
                (Tolerance{1e-3, 0}));
}

TEST_CASE("calibration from E, nu, h, s, sigma_Y and its inverse round trip [SPD eqs. (10)-(13)]")
{
    const ShellMaterial m{2.5e9, 0.35, 1e-3, 2e-2, 4e7};
    const double l = 0.013;
    const ShellLaws laws = calibrate(m, l);
    CHECK_CLOSE(laws.k_s, m.E * m.h / (1 - m.nu * m.nu), (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(laws.k_b / laws.k_s, m.h * m.h / 12, (Tolerance{8 * round_off, 0})); // k_s/k_b = 12/h^2
    CHECK_CLOSE(laws.F_Y, m.h * m.s * m.sigma_Y, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(laws.M_Y, m.h * m.h * l * m.sigma_Y / 3, (Tolerance{8 * round_off, 0})); // 4 I_c sigma_Y / h
    const ShellMaterial back = material_from_laws(laws, m.nu, m.s);
    CHECK_CLOSE(back.E, m.E, (Tolerance{16 * round_off, 0}));
    CHECK_CLOSE(back.h, m.h, (Tolerance{16 * round_off, 0}));
    CHECK_CLOSE(back.sigma_Y, m.sigma_Y, (Tolerance{16 * round_off, 0}));
    // eq. (23): exact tan form; the printed approximation 2 pi/(N s) k_s is twice pi/(N s) k_s.
    const int N = 400;
    const double K = shell_bulk_modulus(laws.k_s, m.s, N);
    CHECK_CLOSE(K, std::numbers::pi / (N * m.s) * laws.k_s, (Tolerance{1e-4, 0})); // tan x = x (1 + x^2/3)
    CHECK_CLOSE(effective_bulk_modulus(core_to_shell_ratio(3 * K, K), K), 4 * K,
                (Tolerance{4 * round_off, 0}));
    const CharacteristicScales c = characteristic_scales(laws.k_b, laws.M_Y, 0.5, l, m.s);
    CHECK_CLOSE(c.M_star, laws.k_b * l / 0.5, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(c.p_star * m.s * l, c.F_star, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(c.sigma_star, c.F_star / (2 * 0.5 * m.s), (Tolerance{4 * round_off, 0}));
}
