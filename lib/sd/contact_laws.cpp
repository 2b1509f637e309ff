#include "sd/contact_laws.hpp"

#include <cmath>
#include <numbers>

namespace softgrain::sd {

double effective_gap(double radius, double h)
{
    return radius * h / (radius + h);
}

ElasticResponse elastic_force_eq3(const Material& m, double a, double delta)
{
    const double stiffness = m.alpha * m.young_modulus;
    return {stiffness * a * delta, stiffness * delta, stiffness * a};
}

InteractionSize interaction_size_eq5(const Material& m, double h, double delta)
{
    const double R = m.radius;
    const double a = std::sqrt(2.0 * R * (effective_gap(R, h) + std::abs(delta)));
    const double d_hbar_d_h = R * R / ((R + h) * (R + h));
    const double sign_delta = delta > 0 ? 1.0 : (delta < 0 ? -1.0 : 0.0);
    return {a, R * d_hbar_d_h / a, R * sign_delta / a};
}

double friction_coefficient_eq4(const Material& m, double a, double h)
{
    const double hbar = effective_gap(m.radius, h);
    return 3.0 * std::numbers::pi * m.viscosity * std::pow(a, 4) / (2.0 * hbar * hbar * hbar);
}

ContactLaws paper_contact_laws(const Material& m)
{
    return {
        [m](double a, double delta) { return elastic_force_eq3(m, a, delta); },
        [](double, double) { return 0.0; },
        [m](double h, double delta) { return interaction_size_eq5(m, h, delta); },
        [m](double a, double h) { return friction_coefficient_eq4(m, a, h); },
    };
}

} // namespace softgrain::sd
