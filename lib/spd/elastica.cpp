#include "spd/elastica.hpp"

#include "core/errors.hpp"
#include "core/gsl_checked.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace softgrain::spd {

namespace {

constexpr double pi = std::numbers::pi;

struct ArcParameters
{
    double kappa0, lambda, c;
};

// y = (x, psi, half gap, quarter area): x' = cos psi, psi' = kappa0 + lambda (x - c),
// (b/2)' = sin psi, A' = x sin psi. Unit radius R = 1.
int arc_rhs(double, const double y[], double dydt[], void* params)
{
    const auto* p = static_cast<const ArcParameters*>(params);
    dydt[0] = std::cos(y[1]);
    dydt[1] = p->kappa0 + p->lambda * (y[0] - p->c);
    dydt[2] = std::sin(y[1]);
    dydt[3] = y[0] * std::sin(y[1]);
    return GSL_SUCCESS;
}

struct ArcEnd
{
    double x, psi, half_gap, quarter_area;
};

ArcEnd integrate_arc(const ArcParameters& p)
{
    ArcParameters params = p;
    gsl_odeiv2_system system{arc_rhs, nullptr, 4, &params};
    gsl_odeiv2_driver* driver = checked_gsl_allocation(
        gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-3, 1e-12, 1e-12),
        "the elastica ODE");
    double s = 0, y[4] = {p.c, 0.0, 0.0, 0.0};
    const int status = gsl_odeiv2_driver_apply(driver, &s, pi / 2 - p.c, y);
    gsl_odeiv2_driver_free(driver);
    if (status != GSL_SUCCESS) throw NumericalError("elastica ODE (GSL rk8pd)", 0, gsl_strerror(status));
    return {y[0], y[1], y[2], y[3]};
}

// Brent root of f on [lo, hi] (f(lo), f(hi) of opposite signs), to 1e-13.
double brent(const std::function<double(double)>& f, double lo, double hi, const char* what)
{
    return brent_root(f, lo, hi, 1e-13, 1e-13, std::string("elastica root (") + what + ")");
}

// lambda such that the tangent is vertical at the end of the quarter arc (inextensibility closes the ring).
double closing_lambda(double kappa0, double c)
{
    const auto mismatch = [&](double lambda) { return integrate_arc({kappa0, lambda, c}).psi - pi / 2; };
    double hi = 1.0;
    while (mismatch(hi) < 0)
        hi *= 2;
    return mismatch(0.0) >= 0 ? 0.0 : brent(mismatch, 0.0, hi, "closing lambda");
}

struct Shape
{
    double strain, width, contact, volume, force;
};

Shape shape(double kappa0, double c)
{
    const double lambda = closing_lambda(kappa0, c);
    const ArcEnd e = integrate_arc({kappa0, lambda, c});
    // int x dy along the arc covers the whole quarter (x >= c on the arc, the flat lies at y = b/2).
    return {1.0 - e.half_gap, e.x, c, 4.0 * e.quarter_area / pi, 2.0 * lambda};
}

} // namespace

double constant_perimeter_ellipse_width(double b)
{
    const auto eq26 = [&](double a) { return 3 * (a + b) - std::sqrt((a + 3 * b) * (3 * a + b)) - 2.0; };
    return b == 1.0 ? 1.0 : brent(eq26, b, 2.0, "eq. (26)");
}

double elastica_flat_contact_onset()
{
    return shape(0.0, 0.0).strain;
}

ElasticaState elastica_ring_between_plates(double strain)
{
    if (!(strain >= 0 && strain < 0.9))
        throw InputError("elastica strain " + std::to_string(strain) + ": allowed [0, 0.9)");
    Shape s;
    if (strain == 0) {
        s = {0.0, 1.0, 0.0, 1.0, 0.0};
    } else if (strain <= elastica_flat_contact_onset()) {
        const double kappa0 =
            brent([&](double k) { return shape(k, 0.0).strain - strain; }, 0.0, 1.0, "kappa_0");
        s = shape(kappa0, 0.0);
    } else {
        double hi = 0.1;
        while (shape(0.0, hi).strain < strain)
            hi = std::min(hi * 1.5, 0.999 * pi / 2);
        const double c =
            brent([&](double cc) { return shape(0.0, cc).strain - strain; }, 0.0, hi, "flat half-length");
        s = shape(0.0, c);
    }
    // b0 = 2R = 2: a/b0 = 2 x_end / 2, L_c/b0 = 2c/2.
    return {strain, s.width, s.contact, s.volume, s.force};
}

} // namespace softgrain::spd
