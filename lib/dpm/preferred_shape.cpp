#include "dpm/preferred_shape.hpp"

#include "core/errors.hpp"
#include "dpm/shape_energy.hpp"

#include <sstream>

namespace softgrain::dpm {

ParameterSpec preferred_shape_parameter_spec(double default_value, bool default_min, std::string description)
{
    ParameterSpec spec = ParameterSpec::real("A0", default_value, "1", std::move(description)).at_least(1.0);
    if (default_min) return spec.keyword_by_default("min");
    return spec.keyword_allowed("min");
}

double preferred_shape_parameter(const Parameters& p, const std::string& name, int nodes)
{
    const double a_min = minimum_shape_parameter(nodes);
    if (p.keyword(name)) return a_min; // the only keyword the spec allows: min
    const double A0 = p.real(name);
    if (A0 < a_min) {
        std::ostringstream message;
        message.precision(6);
        message << "parameter '" << name << "' = " << A0 << " is below A_min(N = " << nodes
                << ") = N tan(pi/N)/pi = " << a_min << "; allowed: a real number >= " << a_min << ", or min";
        throw InputError(message.str());
    }
    return A0;
}

} // namespace softgrain::dpm
