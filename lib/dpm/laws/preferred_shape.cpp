#include "dpm/laws/preferred_shape.hpp"

#include "core/errors.hpp"
#include "dpm/laws/shape_energy.hpp"

#include <sstream>

namespace softgrain::dpm {

double preferred_shape_parameter(std::optional<double> A0, int nodes)
{
    const double a_min = minimum_shape_parameter(nodes);
    if (!A0) return a_min;
    if (*A0 < a_min) {
        std::ostringstream message;
        message.precision(6);
        message << "parameter 'A0' = " << *A0 << " is below A_min(N = " << nodes
                << ") = N tan(pi/N)/pi = " << a_min << "; allowed: a real number >= " << a_min << ", or min";
        throw InputError(message.str());
    }
    return *A0;
}

} // namespace softgrain::dpm
