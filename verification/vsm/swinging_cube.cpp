// Swinging cube (Frenning 2022, section 6.2, eq. (53), Fig. 5): the analytic solution and the convergence
// order.
#include "vsm/swinging_cube.hpp"
#include "core/errors.hpp"
#include "support/tolerance.hpp"
#include "vsm/stability.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>
#include <vector>

using namespace softgrain;
using namespace softgrain::vsm;
using softgrain::verification::Tolerance;

TEST_CASE("eq. (53) solves linear elastodynamics, is volume preserving and meets the BCs [VSM eq. (53)]")
{
    const SwingingCube cube;
    const LameParameters m = cube.material.lame();
    CHECK_CLOSE(cube.amplitude.sum(), 0.0, (Tolerance{0, 1e-18})); // U1 + U2 + U3 = 0 (exact in binary)
    const double h = 1e-3, t = 1.7e-3, dt = 1e-6;
    const double scale = cube.amplitude.norm() * cube.wave_number() * cube.wave_number();
    for (const Vec3& X : {Vec3(0.2, 0.5, 0.7), Vec3(0.9, 0.1, 0.4), Vec3(0.33, 0.66, 0.99)}) {
        // Second derivatives by central differences: grad grad u, and u_tt.
        Eigen::Matrix3d div_grad = Eigen::Matrix3d::Zero(); // column j: d^2 u / dX_j^2
        Vec3 grad_div = Vec3::Zero();
        double divergence = 0;
        for (int j = 0; j < 3; ++j) {
            const Vec3 e = h * Vec3::Unit(j);
            div_grad.col(j) =
                (cube.displacement(X + e, t) - 2 * cube.displacement(X, t) + cube.displacement(X - e, t)) /
                (h * h);
            divergence += (cube.displacement(X + e, t)[j] - cube.displacement(X - e, t)[j]) / (2 * h);
            for (int i = 0; i < 3; ++i) {
                const Vec3 f = h * Vec3::Unit(i);
                // d/dX_i (d u_j / dX_j)
                grad_div[i] += (cube.displacement(X + e + f, t)[j] - cube.displacement(X + e - f, t)[j] -
                                cube.displacement(X - e + f, t)[j] + cube.displacement(X - e - f, t)[j]) /
                               (4 * h * h);
            }
        }
        const Vec3 acceleration =
            (cube.displacement(X, t + dt) - 2 * cube.displacement(X, t) + cube.displacement(X, t - dt)) /
            (dt * dt);
        const Vec3 residual = cube.material.density * acceleration - m.mu * div_grad.rowwise().sum() -
                              (m.lambda + m.mu) * grad_div;
        // Central differences: truncation (k h)^2 / 12 ~ 2e-7 relative; the residual is compared with mu k^2
        // |U|.
        CHECK_CLOSE(residual.norm() / (m.mu * scale), 0.0, (Tolerance{0, 1e-5}));
        CHECK_CLOSE(divergence / (cube.wave_number() * cube.amplitude.norm()), 0.0, (Tolerance{0, 1e-6}));
    }
    // Boundary conditions: u_i = 0 on X_i = 0 (symmetric), tangential u = 0 on X_i = L (antisymmetric).
    const Vec3 P(0.3, 0.6, 0.8);
    for (int i = 0; i < 3; ++i) {
        Vec3 on_zero = P, on_one = P;
        on_zero[i] = 0;
        on_one[i] = cube.length;
        CHECK_CLOSE(cube.displacement(on_zero, 0.0)[i], 0.0, (Tolerance{0, 1e-20}));
        const Vec3 u = cube.displacement(on_one, 0.0);
        CHECK_CLOSE(u.norm() - std::abs(u[i]), 0.0, (Tolerance{0, 1e-19})); // cos(pi/2) ~ 6e-17 times 1e-3 m
    }
}

TEST_CASE("swinging cube converges with order 2 in the particle spacing [VSM Fig. 5: quadratic]")
{
    std::vector<double> log_h, log_error;
    for (int n : {4, 6, 8, 12}) {
        SwingingCubeSetup s;
        s.per_side = n;
        const SwingingCubeResult r = run_swinging_cube(s);
        log_h.push_back(std::log(r.spacing));
        log_error.push_back(std::log(r.displacement_error_l2));
        MESSAGE("n = " << n << ": normalised L2 error " << r.displacement_error_l2);
    }
    double intercept, slope, c00, c01, c11, sum_squares;
    gsl_fit_linear(log_h.data(), 1, log_error.data(), 1, log_h.size(), &intercept, &slope, &c00, &c01, &c11,
                   &sum_squares);
    INFO("fitted order " << slope);
    // The band 2 +- 0.3 for a second-order method. Measured (decision swinging-order): four-point
    // fits between 2.06 and 2.42 for windows from n = 4-12 to n = 20-32, a pre-asymptotic excess that decays
    // to 2; 2.12 here (seeds 1-3: 2.12-2.18). A first-order (1) or third-order (3) method fails the band.
    CHECK(std::abs(slope - 2.0) < 0.3);
}

TEST_CASE("swinging cube error is that of the linear regime: independent of the amplitude [VSM eq. (53)]")
{
    // Eq. (53) solves linear elastodynamics only; the neo-Hookean nonlinearity is O(k |U|) ~ 1.6e-3 relative.
    // A tenfold smaller amplitude must leave the normalised error unchanged to that order.
    SwingingCubeSetup s;
    s.per_side = 8;
    const double full = run_swinging_cube(s).displacement_error_l2;
    s.cube.amplitude *= 0.1;
    const double small = run_swinging_cube(s).displacement_error_l2;
    CHECK_CLOSE(small, full, (Tolerance{1e-2, 0}));
}

TEST_CASE("an unstable swinging cube stops with a diagnosis, never a silent blow-up [VSM section 5]")
{
    // Near incompressibility the neo-Hookean law saturates a leapfrog instability before any J <= 0: at nu =
    // 0.499 and 1.4 times the predicted step (above 2 / omega_max, decision time-step-limit) the run completed
    // with a displacement of 8 times the amplitude. The energy bound of a stable run stops it (exit 3); just
    // below 2 / omega_max (1.35 times the prediction) it completes (decision swinging-blow-up).
    SwingingCubeSetup s;
    s.per_side = 4;
    s.jitter = 0;
    s.cube.material.poisson = 0.499;
    s.end_time = 0.1;
    s.time_step_check = false;
    // The predicted limit as a cfl (dt = cfl L_min / c_p): C_stab c_p / c_eff, 0.548 here.
    const double predicted_cfl =
        stable_cfl_factor * s.cube.material.p_wave_speed() / effective_wave_speed(s.cube.material, s.options);
    s.cfl = 1.4 * predicted_cfl;
    CHECK_THROWS_AS(run_swinging_cube(s), NumericalError);
    s.cfl = 1.35 * predicted_cfl;
    CHECK(run_swinging_cube(s).displacement_error_l2 < 0.2);
}
