#include "sd/pair_dynamics.hpp"

#include "core/errors.hpp"
#include "core/gsl_checked.hpp"

#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <memory>
#include <string>

namespace softgrain::sd {

double deflection_eq2(double radius, double X, double h)
{
    return (2.0 * radius + h - X) / 2.0;
}

PairRates soft_dynamics_rates(const ContactLaws& laws, double radius, double X, double h, double F_ext,
                              double F_ext_rate)
{
    PairRates r;
    r.delta = deflection_eq2(radius, X, h);
    const InteractionSize size = laws.size(h, r.delta);
    r.a = size.a;
    r.zeta = laws.friction(r.a, h);
    const ElasticResponse elastic = laws.elastic(r.a, r.delta);
    r.F_ela = elastic.force;
    r.F_adh = laws.remote(r.a, h);
    // Substituting a-dot = a_h h-dot + a_delta delta-dot and 2 delta-dot = h-dot - X-dot into eq. (8).
    r.C = (elastic.d_a * size.d_delta + elastic.d_delta) / 2.0;
    r.D = r.C * r.zeta / (r.C + elastic.d_a * size.d_h);
    r.h_dot = -(F_ext - r.F_adh) / r.zeta;                 // eq. (7)
    r.X_dot = -F_ext_rate / r.C - (F_ext - r.F_adh) / r.D; // eq. (9)
    return r;
}

double balanced_deflection(const ContactLaws& laws, double h, double F_ext)
{
    if (F_ext == 0) return 0.0;
    struct Problem
    {
        const ContactLaws* laws;
        double h, F;
    } problem{&laws, h, F_ext};
    gsl_function residual{[](double delta, void* p) {
                              const auto* q = static_cast<const Problem*>(p);
                              return q->laws->elastic(q->laws->size(q->h, delta).a, delta).force - q->F;
                          },
                          &problem};
    double upper = 1e-12 * (1.0 + h);
    while (GSL_FN_EVAL(&residual, upper) < 0) {
        upper *= 2.0;
        if (!std::isfinite(upper) || upper > 1e30)
            throw NumericalError("deflection balancing F_ext = " + std::to_string(F_ext), 0,
                                 "F_ela(a(h, delta), delta) never reaches F_ext: the elastic law is bounded");
    }
    const double lower = upper / 2.0 > 1e-12 * (1.0 + h) ? upper / 2.0 : 0.0;
    // Relative tolerance 1e-15: delta to round-off, so that eq. (1) balances to its last digits.
    return brent_root([&](double delta) { return GSL_FN_EVAL(&residual, delta); }, lower, upper, 0.0, 1e-15,
                      "deflection balancing F_ext = " + std::to_string(F_ext) + " (force balance eq. (1))");
}

Loading constant_loading(double force)
{
    return {[force](double) { return force; }, [](double) { return 0.0; }};
}

} // namespace softgrain::sd
