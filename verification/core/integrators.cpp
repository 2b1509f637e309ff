// Viscous damping in leapfrog and velocity Verlet against the damped-oscillator solution: the order.
#include "core/integrators.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <gsl/gsl_fit.h>
#include <vector>

using namespace softgrain;

namespace {

// Damped oscillator m x'' = -k x - c x', x(0) = 1, v(0) = 0, integrated to t_end; returns x(t_end) error.
template <class Step>
double damped_position_error(double dt, Step&& step, bool leapfrog)
{
    const double m = 1.0, k = 4.0, c = 0.4, t_end = 5.0;
    const double gamma = c / (2 * m), omega_d = std::sqrt(k / m - gamma * gamma);
    const auto exact_x = [&](double t) {
        return std::exp(-gamma * t) * (std::cos(omega_d * t) + gamma / omega_d * std::sin(omega_d * t));
    };
    Eigen::VectorXd x(1), v(1), f(1), inverse_mass(1);
    x << 1.0;
    v << 0.0;
    inverse_mass << 1.0 / m;
    const auto force = [&](const Eigen::VectorXd& position, const Eigen::VectorXd& velocity,
                           Eigen::VectorXd& out) {
        out = -k * position;
        add_viscous_damping(out, velocity, c);
    };
    if (leapfrog) {
        // v(-dt/2) from the exact solution, so that the start adds no first-order error.
        const double a0 = -k / m;
        v[0] = -0.5 * dt * a0;
    } else {
        force(x, v, f);
    }
    const long steps = std::lround(t_end / dt);
    for (long n = 0; n < steps; ++n)
        step(x, v, f, inverse_mass, dt, force);
    return std::abs(x[0] - exact_x(t_end));
}

template <class Step>
double fitted_order(Step&& step, bool leapfrog)
{
    std::vector<double> log_dt, log_error;
    for (double dt = 0.02; dt > 0.002; dt /= 2) {
        log_dt.push_back(std::log(dt));
        log_error.push_back(std::log(damped_position_error(dt, step, leapfrog)));
    }
    double intercept, slope, c00, c01, c11, ss;
    gsl_fit_linear(log_dt.data(), 1, log_error.data(), 1, log_dt.size(), &intercept, &slope, &c00, &c01, &c11,
                   &ss);
    return slope;
}

} // namespace

TEST_CASE(
    "leapfrog with viscous damping is first order: the damping velocity lags by dt/2 [damped oscillator]")
{
    // The damping force uses v(t - dt/2) instead of v(t): a local error c dt/2 |v| dt per step, so the global
    // error is O(dt). (Without damping the scheme is second order: harmonic.cpp.) Measured 1.02; the band
    // +-0.1 covers the O(dt^2) contamination at the coarsest dt = 0.02 = T/16.
    const double order = fitted_order([](auto& x, auto& v, auto& f, const auto& im, double dt,
                                         auto&& force) { leapfrog_step(x, v, f, im, dt, force); },
                                      true);
    INFO("fitted order " << order);
    CHECK(std::abs(order - 1.0) < 0.1);
}

TEST_CASE("velocity Verlet with viscous damping is first order: the half-step velocity lags by dt/2")
{
    // compute_force sees v(t) + dt/2 a(t), the velocity of t + dt/2, for the force at t + dt: the same lag
    // as leapfrog, hence first order (measured 1.02).
    const double order = fitted_order([](auto& x, auto& v, auto& f, const auto& im, double dt,
                                         auto&& force) { velocity_verlet_step(x, v, f, im, dt, force); },
                                      false);
    INFO("fitted order " << order);
    CHECK(std::abs(order - 1.0) < 0.1);
}
