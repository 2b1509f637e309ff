// FIRE minimiser (Bitzek et al. 2006) on functions with known minima, and its stopping rule.
#include "core/fire.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <string>

using namespace softgrain;
using softgrain::verification::Tolerance;

TEST_CASE("FIRE finds the minimum of an ill-conditioned quadratic to the force tolerance")
{
    // U = 1/2 sum_i k_i (x_i - c_i)^2 with stiffness ratio 1e3: at the minimum x = c.
    const Eigen::VectorXd k = (Eigen::VectorXd(4) << 1.0, 10.0, 100.0, 1000.0).finished();
    const Eigen::VectorXd c = (Eigen::VectorXd(4) << 0.5, -1.0, 2.0, 0.1).finished();
    const EnergyAndForce quadratic = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
        f = -(k.array() * (x - c).array()).matrix();
        return 0.5 * (k.array() * (x - c).array().square()).sum();
    };
    Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
    FireOptions options;
    options.dt_initial = 1e-3;
    options.dt_max = 1e-2; // below the stability limit 2/sqrt(k_max) = 0.063 of the MD step
    options.force_tolerance = 1e-12;
    const FireResult result = fire_minimise(x, quadratic, options);
    REQUIRE(result.converged);
    CHECK(result.force_rms < 1e-12);
    // |x_i - c_i| = |f_i| / k_i <= f_rms sqrt(n) / k_min: the stopping rule bounds the position error.
    for (int i = 0; i < 4; ++i)
        CHECK_CLOSE(x[i], c[i], (Tolerance{0, 1e-12 * 2.0 / 1.0}));
}

TEST_CASE("FIRE reaches the minimum (1, 1) of the Rosenbrock function")
{
    const EnergyAndForce rosenbrock = [](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
        const double a = 1.0 - x[0], b = x[1] - x[0] * x[0];
        f[0] = 2.0 * a + 400.0 * x[0] * b;
        f[1] = -200.0 * b;
        return a * a + 100.0 * b * b;
    };
    Eigen::VectorXd x = Eigen::Vector2d(-1.2, 1.0);
    FireOptions options;
    options.dt_initial = 1e-4;
    options.dt_max = 2e-3;
    options.force_tolerance = 1e-10;
    const FireResult result = fire_minimise(x, rosenbrock, options);
    REQUIRE(result.converged);
    // Near (1,1) the Hessian's smallest eigenvalue is ~0.4: position error <= |f| / 0.4 ~ 1e-9.
    CHECK_CLOSE(x[0], 1.0, (Tolerance{0, 1e-8}));
    CHECK_CLOSE(x[1], 1.0, (Tolerance{0, 1e-8}));
    CHECK(result.energy < 1e-16);
}

TEST_CASE("FIRE reports non-convergence when the iteration budget is exhausted")
{
    // A constant force 2.5e-9 per degree of freedom (no minimum), above the force tolerance 1e-10.
    const EnergyAndForce slope = [](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
        f.setConstant(2.5e-9);
        return -2.5e-9 * x.sum();
    };
    Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
    FireOptions options;
    options.max_iterations = 100;
    const FireResult result = fire_minimise(x, slope, options);
    CHECK_FALSE(result.converged);
    CHECK(result.iterations == 100);
    CHECK(result.force_rms == doctest::Approx(2.5e-9).epsilon(1e-14));
    // Always downhill: the velocity only grows, 0.5 |v|^2 / 3 with v_i >= 100 dt_initial f_i.
    CHECK(result.kinetic >= 0.5 * std::pow(100 * options.dt_initial * 2.5e-9, 2));

    // The diagnosis prints small values in scientific notation, not as 0.000000.
    const std::string why = fire_shortfall(result, options);
    CHECK(why.find("after 100 iterations: force rms 2.5e-09 (tolerance 1e-10)") != std::string::npos);
    CHECK(why.find("(tolerance 1e-20)") != std::string::npos);
}
