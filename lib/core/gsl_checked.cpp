#include "core/gsl_checked.hpp"

#include "core/errors.hpp"

#include <memory>
#include <sstream>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

namespace softgrain {

void use_status_codes_for_gsl_errors()
{
    gsl_set_error_handler_off();
}

void throw_gsl_allocation_failure(const std::string& what)
{
    throw NumericalError("setting up " + what + " (GSL returned no object)", 0,
                         "arguments GSL refuses (a step or tolerance that is not positive and finite) or no "
                         "memory left");
}

double brent_root(const std::function<double(double)>& f, double lower, double upper, double abs_tolerance,
                  double rel_tolerance, const std::string& what)
{
    constexpr int max_iterations = 200;
    gsl_function function{
        [](double x, void* fn) { return (*static_cast<const std::function<double(double)>*>(fn))(x); },
        const_cast<std::function<double(double)>*>(&f)};
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        checked_gsl_allocation(gsl_root_fsolver_alloc(gsl_root_fsolver_brent), what + " (Brent solver)"),
        gsl_root_fsolver_free);
    if (const int status = gsl_root_fsolver_set(solver.get(), &function, lower, upper);
        status != GSL_SUCCESS) {
        std::ostringstream bracket; // shortest form: a bracket may reach 1e308
        bracket << what << " (Brent, bracket [" << lower << ", " << upper << "])";
        throw NumericalError(bracket.str(), 0, gsl_strerror(status));
    }
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
        if (const int status = gsl_root_fsolver_iterate(solver.get()); status != GSL_SUCCESS)
            throw NumericalError(what + " (Brent)", iteration, gsl_strerror(status));
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                                   gsl_root_fsolver_x_upper(solver.get()), abs_tolerance,
                                   rel_tolerance) == GSL_SUCCESS)
            return gsl_root_fsolver_root(solver.get());
    }
    throw NumericalError(what + " (Brent)", max_iterations, "the bracket did not shrink to the tolerance");
}

} // namespace softgrain
