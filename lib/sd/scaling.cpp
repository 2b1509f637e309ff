#include "sd/scaling.hpp"

#include <cmath>
#include <gsl/gsl_poly.h>

namespace softgrain::sd {

LocalExponents local_exponents(const std::vector<ApproachSample>& samples)
{
    const std::size_t n = samples.size();
    LocalExponents e{std::vector<double>(n, NAN), std::vector<double>(n, NAN)};
    if (n < 3) return e;
    std::vector<double> x(n), u(n), v(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = std::log(samples[i].h);
        u[i] = std::log(std::abs(samples[i].rates.delta));
        v[i] = std::log(std::abs(samples[i].rates.h_dot));
    }
    // Derivative at x[i] of the parabola through (x[j], f[j]), j = a, b, c.
    const auto derivative = [&](const std::vector<double>& f, std::size_t i, std::size_t a, std::size_t b,
                                std::size_t c) {
        const double la = (2 * x[i] - x[b] - x[c]) / ((x[a] - x[b]) * (x[a] - x[c]));
        const double lb = (2 * x[i] - x[a] - x[c]) / ((x[b] - x[a]) * (x[b] - x[c]));
        const double lc = (2 * x[i] - x[a] - x[b]) / ((x[c] - x[a]) * (x[c] - x[b]));
        return la * f[a] + lb * f[b] + lc * f[c];
    };
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i == 0 ? 0 : (i == n - 1 ? n - 3 : i - 1);
        e.lambda1[i] = derivative(u, i, a, a + 1, a + 2);
        e.lambda2[i] = derivative(v, i, a, a + 1, a + 2);
    }
    return e;
}

namespace {
double g_of(double R, double h)
{
    return h * R * R / ((R + h) * (R + h));
} // h dh-bar/dh
} // namespace

double lambda1_paper(const Material& m, double h, double delta)
{
    return -g_of(m.radius, h) / (2.0 * effective_gap(m.radius, h) + 3.0 * delta);
}

double lambda2_paper(const Material& m, double h, double delta)
{
    const double hbar = effective_gap(m.radius, h), g = g_of(m.radius, h);
    return 3.0 * g / hbar - 2.0 * (g + lambda1_paper(m, h, delta) * delta) / (hbar + delta);
}

double regime_width(Regime regime, double R, double h, double delta)
{
    switch (regime) {
    case Regime::stokes:
        return (R / h) * (3.0 - 2.0 * R / (R + delta));
    case Regime::poiseuille:
        return h / R + 3.0 * delta / h;
    case Regime::hertz:
        return 3.0 * h / R + 4.0 / 3.0 * h / delta;
    }
    return NAN;
}

double lambda1_limit(Regime regime)
{
    return regime == Regime::poiseuille ? -0.5 : 0.0;
}
double lambda2_limit(Regime regime)
{
    return regime == Regime::stokes ? 0.0 : (regime == Regime::poiseuille ? 1.0 : 3.0);
}

double crossover_kappa_paper(const Material& m, double h)
{
    const double R = m.radius;
    return m.alpha * std::sqrt(2.0) * (h / R) * std::sqrt(effective_gap(R, h) / R + h / R);
}

double crossover_kappa_asymptotic(const Material& m, double h)
{
    return 2.0 * m.alpha * std::pow(h / m.radius, 1.5);
}

double balanced_deflection_paper(const Material& m, double h, double force)
{
    const double R = m.radius;
    const double kappa = force / (m.young_modulus * R * R);
    // d^3 + b d^2 - c = 0 in d = delta/R, b = h-bar/R, c = kappa^2/(2 alpha^2): one positive root.
    const double b = effective_gap(R, h) / R, c = kappa * kappa / (2.0 * m.alpha * m.alpha);
    double roots[3];
    const int count = gsl_poly_solve_cubic(b, 0.0, -c, &roots[0], &roots[1], &roots[2]);
    double d = roots[count - 1]; // the largest real root is the positive one
    // One Newton step polishes the trigonometric/Cardano root to round-off when c << b^3.
    d -= (d * d * (d + b) - c) / (d * (3.0 * d + 2.0 * b));
    return d * R;
}

} // namespace softgrain::sd
