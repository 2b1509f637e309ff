#include "core/harmonic.hpp"

#include "core/errors.hpp"
#include "core/integrators.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace softgrain {

double HarmonicOscillator::angular_frequency() const
{
    return std::sqrt(stiffness / mass);
}
double HarmonicOscillator::period() const
{
    return 2.0 * std::numbers::pi / angular_frequency();
}
double HarmonicOscillator::critical_time_step() const
{
    return 2.0 / angular_frequency();
}

double verlet_period(const HarmonicOscillator& oscillator, double dt)
{
    const double discrete_omega = 2.0 / dt * std::asin(0.5 * oscillator.angular_frequency() * dt);
    return 2.0 * std::numbers::pi / discrete_omega;
}

double verlet_energy_error_bound(const HarmonicOscillator& oscillator, double dt)
{
    const double ratio = dt / oscillator.critical_time_step();
    return ratio * ratio;
}

long harmonic_step_count(const HarmonicOscillator& oscillator, double dt, double periods)
{
    // Refused before the run when the steps cannot be taken: a mass so small that omega overflows (a period
    // of 0: no step), or a dt so small that the count overflows (dt = 1e-300).
    constexpr double max_steps = 1e10;
    const double wanted = std::ceil(periods * oscillator.period() / dt);
    if (!(wanted >= 1 && wanted <= max_steps))
        throw InputError("periods = " + number_text(periods) +
                         " of T = 2 pi sqrt(m/k) = " + number_text(oscillator.period()) +
                         " s at dt = " + number_text(dt) + " s ask for " + number_text(wanted) +
                         " steps; allowed: 1 to 1e10 steps (check mass, stiffness, dt)");
    return static_cast<long>(wanted);
}

namespace {

std::string instability_cause(const HarmonicOscillator& oscillator, double dt)
{
    std::ostringstream cause;
    const double dt_c = oscillator.critical_time_step();
    if (dt >= dt_c)
        cause << "time step dt = " << dt
              << " s is at or above the stability limit of velocity Verlet, dt_c = "
              << "2 sqrt(m/k) = " << dt_c << " s (dt/dt_c = " << dt / dt_c << "); choose dt < dt_c";
    else
        cause << "energy growth below the stability limit (dt/dt_c = " << dt / dt_c
              << "): a defect, please report";
    return cause.str();
}

} // namespace

HarmonicRun simulate_harmonic(const HarmonicOscillator& oscillator, double dt, double periods,
                              const HarmonicObserver& observe)
{
    const double k = oscillator.stiffness, m = oscillator.mass;
    const auto energy = [&](double x, double v) { return 0.5 * m * v * v + 0.5 * k * x * x; };
    const auto spring_force = [&](const Eigen::VectorXd& x, const Eigen::VectorXd&, Eigen::VectorXd& f) {
        f = -k * x;
    };

    Eigen::VectorXd x(1), v(1), f(1), inverse_mass(1);
    x << 1.0;
    v << 0.0;
    inverse_mass << 1.0 / m;
    spring_force(x, v, f);
    const double e0 = energy(x[0], v[0]);

    HarmonicRun run;
    const long steps = harmonic_step_count(oscillator, dt, periods);
    std::vector<double> upward_crossings;
    for (long n = 1; n <= steps; ++n) {
        const double x_before = x[0];
        velocity_verlet_step(x, v, f, inverse_mass, dt, spring_force);
        const double t = n * dt;
        const double relative_error = energy(x[0], v[0]) / e0 - 1.0;
        if (!std::isfinite(relative_error) || relative_error > 3.0)
            throw NumericalError("energy E/E0 = " + std::to_string(relative_error + 1.0), n,
                                 instability_cause(oscillator, dt));
        run.energy_error_max = std::max(run.energy_error_max, std::abs(relative_error));
        if (x_before < 0 && x[0] >= 0) // linear interpolation of the crossing: exact up to O(dt^3) at x = 0
            upward_crossings.push_back(t - dt * x[0] / (x[0] - x_before));
        if (observe) observe(t, x[0], v[0], relative_error);
    }
    run.steps = steps;
    if (upward_crossings.size() >= 2)
        run.period = (upward_crossings.back() - upward_crossings.front()) /
                     static_cast<double>(upward_crossings.size() - 1);
    else
        run.period = std::nan("");
    return run;
}

} // namespace softgrain
