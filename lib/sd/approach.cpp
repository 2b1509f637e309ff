#include "sd/approach.hpp"

#include "core/errors.hpp"
#include "core/gsl_checked.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <memory>
#include <sstream>

namespace softgrain::sd {

namespace {

const gsl_odeiv2_step_type* step_type(const std::string& name)
{
    if (name == "rk2") return gsl_odeiv2_step_rk2;
    if (name == "rk4") return gsl_odeiv2_step_rk4;
    if (name == "rkf45") return gsl_odeiv2_step_rkf45;
    if (name == "rkck") return gsl_odeiv2_step_rkck;
    if (name == "rk8pd") return gsl_odeiv2_step_rk8pd;
    if (name == "rk1imp") return gsl_odeiv2_step_rk1imp;
    if (name == "rk2imp") return gsl_odeiv2_step_rk2imp;
    if (name == "rk4imp") return gsl_odeiv2_step_rk4imp;
    if (name == "bsimp") return gsl_odeiv2_step_bsimp;
    if (name == "msadams") return gsl_odeiv2_step_msadams;
    return gsl_odeiv2_step_msbdf;
}

// The ODE system handed to GSL: y = (X, h), f = (X-dot, h-dot) from eqs. (9) and (7).
struct System
{
    const ApproachProblem* problem;
    long evaluations = 0;
};

PairRates rates_at(const ApproachProblem& p, double t, double X, double h)
{
    return soft_dynamics_rates(p.laws, p.material.radius, X, h, p.loading.force(t), p.loading.rate(t));
}

int rhs(double t, const double y[], double f[], void* params)
{
    auto* s = static_cast<System*>(params);
    ++s->evaluations;
    // A trial step that reaches h <= 0 is refused (GSL_FAILURE: the step is retried smaller).
    if (!(y[1] > 0) || !std::isfinite(y[0])) return GSL_FAILURE;
    const PairRates r = rates_at(*s->problem, t, y[0], y[1]);
    f[0] = r.X_dot;
    f[1] = r.h_dot;
    return std::isfinite(f[0]) && std::isfinite(f[1]) ? GSL_SUCCESS : GSL_FAILURE;
}

// Jacobian for the implicit steppers (and jacobian_modes), by central differences. Both X and h move
// delta = (2R + h - X)/2, and the rates vary on the scale of min(delta, h): steps 1e-6 min(delta, h), but
// never below 1e3 eps |X|, where the round-off of delta would dominate (relative accuracy 1e-3 at worst,
// when delta/X ~ 1e-8).
int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* params)
{
    auto* s = static_cast<System*>(params);
    const double R = s->problem->material.radius;
    const double delta = std::abs(deflection_eq2(R, y[0], y[1]));
    const double step = std::max(1e-6 * std::min(delta, y[1]), 1e3 * DBL_EPSILON * std::abs(y[0]));
    const double steps[2] = {step, std::min(step, 0.5 * y[1])};
    double plus[2], minus[2];
    for (int j = 0; j < 2; ++j) {
        double yp[2] = {y[0], y[1]}, ym[2] = {y[0], y[1]};
        yp[j] += steps[j];
        ym[j] -= steps[j];
        if (rhs(t, yp, plus, params) != GSL_SUCCESS || rhs(t, ym, minus, params) != GSL_SUCCESS)
            return GSL_FAILURE;
        for (int i = 0; i < 2; ++i)
            dfdy[i * 2 + j] = (plus[i] - minus[i]) / (2.0 * steps[j]);
    }
    const double tau = 1e-6 * std::max(std::abs(t), 1.0);
    if (rhs(t + tau, y, plus, params) != GSL_SUCCESS || rhs(t - tau, y, minus, params) != GSL_SUCCESS)
        return GSL_FAILURE;
    for (int i = 0; i < 2; ++i)
        dfdt[i] = (plus[i] - minus[i]) / (2.0 * tau);
    return GSL_SUCCESS;
}

// Step-size control on the relative errors of delta and h. GSL's standard controls weigh each component by
// its own size; X ~ 2R would then hide the error of delta = (2R + h - X)/2. The levels are refreshed at every
// output (delta and h change by a few % between outputs). hadjust follows GSL's standard control.
struct ControlState
{
    double level[2] = {1, 1}; // allowed local error of X and of h
};

int control_hadjust(void* state, size_t dim, unsigned int order, const double[], const double yerr[],
                    const double[], double* step)
{
    const auto* c = static_cast<const ControlState*>(state);
    double ratio = DBL_MIN;
    for (size_t i = 0; i < dim; ++i)
        ratio = std::max(ratio, std::abs(yerr[i]) / c->level[i]);
    const double safety = 0.9;
    if (ratio > 1.1) {
        *step *= std::max(safety / std::pow(ratio, 1.0 / order), 0.2);
        return GSL_ODEIV_HADJ_DEC;
    }
    if (ratio < 0.5) {
        *step *= std::clamp(safety / std::pow(ratio, 1.0 / (order + 1.0)), 1.0, 5.0);
        return GSL_ODEIV_HADJ_INC;
    }
    return GSL_ODEIV_HADJ_NIL;
}

const gsl_odeiv2_control_type delta_h_control = {
    "relative error of delta (eq. 2) and h",
    []() -> void* { return new ControlState; },
    [](void*, double, double, double, double) -> int { return GSL_SUCCESS; },
    control_hadjust,
    [](void* state, double, double, double, size_t ind, double* level) -> int {
        *level = static_cast<const ControlState*>(state)->level[ind];
        return GSL_SUCCESS;
    },
    [](void*, const gsl_odeiv2_driver*) -> int { return GSL_SUCCESS; },
    [](void* state) { delete static_cast<ControlState*>(state); },
};

void set_levels(gsl_odeiv2_control* control, const ApproachProblem& p, const double y[], double tolerance)
{
    auto* c = static_cast<ControlState*>(control->state);
    const double delta = std::abs(deflection_eq2(p.material.radius, y[0], y[1]));
    c->level[0] = tolerance * delta + 8.0 * DBL_EPSILON * std::abs(y[0]);
    c->level[1] = tolerance * y[1];
}

struct DriverDeleter
{
    void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

std::string describe(double value)
{
    return number_text(value, 4);
}

} // namespace

const std::vector<Stepper>& gsl_steppers()
{
    static const std::vector<Stepper> steppers = {
        {"rk2", false, 0},   {"rk4", false, 1},     {"rkf45", false, 2}, {"rkck", false, 3},
        {"rk8pd", false, 4}, {"msadams", false, 5}, {"rk1imp", true, 6}, {"rk2imp", true, 7},
        {"rk4imp", true, 8}, {"bsimp", true, 9},    {"msbdf", true, 10},
    };
    return steppers;
}

const Stepper& find_stepper(const std::string& name)
{
    for (const auto& s : gsl_steppers())
        if (s.name == name) return s;
    std::string known;
    for (const auto& s : gsl_steppers())
        known += " " + s.name;
    throw InputError("stepper = '" + name + "' is not a GSL stepper; allowed:" + known);
}

double gap_rate_derivative(const ApproachProblem& p, double h, double t)
{
    const double F = p.loading.force(t);
    const auto balanced_rate = [&](double gap) {
        const double delta = balanced_deflection(p.laws, gap, F);
        const double a = p.laws.size(gap, delta).a;
        return -(F - p.laws.remote(a, gap)) / p.laws.friction(a, gap);
    };
    const double step = 1e-4 * h;
    return (balanced_rate(h + step) - balanced_rate(h - step)) / (2.0 * step);
}

ModeRates jacobian_modes(const ApproachProblem& p, double t, double X, double h)
{
    System system{&p};
    const double y[2] = {X, h};
    double J[4], dfdt[2];
    if (jacobian(t, y, J, dfdt, &system) != GSL_SUCCESS)
        throw NumericalError("Jacobian of eqs. (7), (9)", 0, "rates not finite near h = " + describe(h));
    const double trace = J[0] + J[3], det = J[0] * J[3] - J[1] * J[2];
    const double discriminant = trace * trace / 4 - det;
    const double root = discriminant > 0 ? std::sqrt(discriminant) : 0.0; // complex pair: equal real parts
    const double tau = h / std::abs(rates_at(p, t, X, h).h_dot);
    return {(trace / 2 - root) * tau, (trace / 2 + root) * tau};
}

double approach_time_reference(const ApproachProblem& p, double h_from, double h_to)
{
    const double F = p.loading.force(0.0);
    struct Integrand
    {
        const ApproachProblem* p;
        double F;
    } data{&p, F};
    gsl_function f{[](double ln_h, void* q) {
                       const auto* d = static_cast<const Integrand*>(q);
                       const double h = std::exp(ln_h);
                       const double delta = balanced_deflection(d->p->laws, h, d->F);
                       const double a = d->p->laws.size(h, delta).a;
                       return d->p->laws.friction(a, h) * h / (d->F - d->p->laws.remote(a, h));
                   },
                   &data};
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> workspace(
        gsl_integration_workspace_alloc(2000), gsl_integration_workspace_free);
    double result = 0, error = 0;
    const int status = gsl_integration_qag(&f, std::log(h_to), std::log(h_from), 0.0, 1e-13, 2000,
                                           GSL_INTEG_GAUSS41, workspace.get(), &result, &error);
    if (status != GSL_SUCCESS && error > 1e-10 * std::abs(result))
        throw NumericalError("reference approach time (quadrature of eq. 7)", 0, gsl_strerror(status));
    return result;
}

ApproachRun integrate_approach(const ApproachProblem& p, const IntegratorSettings& settings)
{
    const Stepper& stepper = find_stepper(settings.stepper);
    const double R = p.material.radius;
    System system{&p};
    gsl_odeiv2_system ode{rhs, jacobian, 2, &system};

    double t = 0;
    const double delta0 = balanced_deflection(p.laws, p.h0, p.loading.force(0.0));
    double y[2] = {2.0 * R + p.h0 - 2.0 * delta0, p.h0}; // eq. (2) with the balanced delta0 of eq. (1)
    const PairRates initial = rates_at(p, t, y[0], y[1]);
    const double tau0 = p.h0 / std::abs(initial.h_dot);

    const double first_step = settings.fixed_step ? settings.dt : 1e-3 * tau0;
    std::unique_ptr<gsl_odeiv2_driver, DriverDeleter> driver(checked_gsl_allocation(
        gsl_odeiv2_driver_alloc_y_new(&ode, step_type(stepper.name), first_step, settings.tolerance, 0.0),
        "the approach ODE (" + stepper.name + ")"));
    // Replace GSL's control by the delta-and-h control (the driver frees whatever control it holds).
    gsl_odeiv2_control_free(driver->c);
    driver->c = checked_gsl_allocation(gsl_odeiv2_control_alloc(&delta_h_control), "the delta-and-h control");
    gsl_odeiv2_control_set_driver(driver->c, driver.get());
    gsl_odeiv2_driver_set_nmax(driver.get(), static_cast<unsigned long>(settings.max_steps));

    ApproachRun run;
    const auto record = [&] {
        run.samples.push_back({t, y[0], y[1], p.loading.force(t), rates_at(p, t, y[0], y[1])});
    };
    record();
    const double log_spacing = std::log(10.0) / settings.samples_per_decade;
    const auto failure = [&](const std::string& what, const std::string& cause) {
        return NumericalError(what + " (stepper " + stepper.name + ", t = " + describe(t) +
                                  ", h = " + describe(y[1]) + ")",
                              run.steps, cause);
    };

    if (settings.fixed_step) {
        double last_sample_h = y[1], previous_h = y[1], previous_rate = initial.h_dot;
        while (y[1] > p.h_min) {
            const int status = gsl_odeiv2_driver_apply_fixed_step(driver.get(), &t, settings.dt, 1, y);
            ++run.steps;
            const bool finite =
                status == GSL_SUCCESS && std::isfinite(y[0]) && std::isfinite(y[1]) && y[1] > 0;
            const double rate = finite ? rates_at(p, t, y[0], y[1]).h_dot : NAN;
            // dt |d h-dot/dh| measured along the trajectory: the explicit stability parameter of this step.
            const double dt_lambda =
                finite && y[1] != previous_h
                    ? settings.dt * std::abs((rate - previous_rate) / (y[1] - previous_h))
                    : 0;
            run.dt_lambda_max = std::max(run.dt_lambda_max, dt_lambda);
            const bool compressive = previous_rate < 0;
            if (status != GSL_SUCCESS || !finite || !std::isfinite(rate) ||
                (compressive && y[1] >= previous_h)) {
                const std::string symptom =
                    status != GSL_SUCCESS ? "a stage of the fixed step reached h <= 0 (rates refused)"
                    : !finite             ? "the gap left h > 0"
                                          : "the gap grew under a compressive load (amplification > 1)";
                throw failure(symptom,
                              "the fixed step dt = " + describe(settings.dt) + " gives dt |d h-dot/dh| = " +
                                  describe(settings.dt * std::abs(gap_rate_derivative(p, previous_h, t))) +
                                  " at h = " + describe(previous_h) +
                                  ", of order 1 or more: the step overshoots the gap (positivity) or "
                                  "exceeds the stepper's stability bound; use an adaptive step or a "
                                  "smaller dt");
            }
            if (run.steps >= settings.max_steps)
                throw failure("h did not reach h_min", "max_steps too small for this fixed step");
            previous_h = y[1];
            previous_rate = rate;
            if (std::log(last_sample_h / y[1]) >= log_spacing || y[1] <= p.h_min) {
                record();
                last_sample_h = y[1];
            }
        }
    } else {
        double exponent = 0; // local d ln|h-dot| / d ln h, to predict the time of the next sample
        while (y[1] > p.h_min * (1.0 + 1e-9)) {
            const ApproachSample& last = run.samples.back();
            const double drop = std::min(log_spacing, std::log(y[1] / p.h_min));
            const double tau = y[1] / std::abs(last.rates.h_dot);
            // Time for ln h to drop by `drop` if h-dot ~ h^exponent:
            //   tau (e^{(exponent-1) drop} - 1)/(exponent - 1).
            const double dt = std::abs(exponent - 1.0) < 1e-6
                                  ? tau * drop
                                  : tau * std::expm1((exponent - 1.0) * drop) / (exponent - 1.0);
            set_levels(driver->c, p, y, settings.tolerance);
            const int status = gsl_odeiv2_driver_apply(driver.get(), &t, t + dt, y);
            run.steps += static_cast<long>(driver->n); // the driver counts the steps of each call from zero
            if (status != GSL_SUCCESS)
                throw failure("adaptive integration of eqs. (7), (9) failed: " +
                                  std::string(gsl_strerror(status)),
                              "step size underflow or max_steps reached (tolerance below round-off?)");
            const double h_previous = last.h, rate_previous = last.rates.h_dot;
            record();
            exponent = std::log(run.samples.back().rates.h_dot / rate_previous) / std::log(y[1] / h_previous);
            if (!std::isfinite(exponent)) exponent = 0;
        }
    }
    run.rhs_evaluations = system.evaluations;
    return run;
}

} // namespace softgrain::sd
