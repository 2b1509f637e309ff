// GSL under softgrain's error contract. GSL's default error handler calls abort(): a bad input or a
// non-finite function value would kill the process (exit 134) and leave a partial directory behind.
// softgrain turns that handler off, so every GSL call returns its status, and checks the statuses of the
// calls it makes: a failure becomes a NumericalError (exit 3) that names what failed. (Throwing from a GSL
// handler instead would unwind through C frames that Debian's GSL builds without -fexceptions.)
#pragma once

#include <functional>
#include <string>

namespace softgrain {

// Turns GSL's abort-on-error handler off for the whole program (idempotent); call it before any GSL use.
void use_status_codes_for_gsl_errors();

[[noreturn]] void throw_gsl_allocation_failure(const std::string& what);

// A GSL allocation that returned NULL (with the handler off: bad arguments or no memory) as a NumericalError.
template <class T>
T* checked_gsl_allocation(T* allocated, const std::string& what)
{
    if (!allocated) throw_gsl_allocation_failure(what);
    return allocated;
}

// The root of f in [lower, upper] (f(lower), f(upper) of opposite signs) by Brent's method (GSL), to
// |upper - lower| < abs_tolerance + rel_tolerance |root| (gsl_root_test_interval). Throws a NumericalError
// naming `what` when the bracket is invalid, f is not finite, or 200 iterations do not converge.
double brent_root(const std::function<double(double)>& f, double lower, double upper, double abs_tolerance,
                  double rel_tolerance, const std::string& what);

} // namespace softgrain
