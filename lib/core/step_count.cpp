#include "core/step_count.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace softgrain {

long checked_step_count(double count, const std::string& what, const std::string& key, double value)
{
    if (std::isfinite(count) && count <= max_time_steps) return static_cast<long>(count);
    std::string message = "'" + key + "' = " + number_text(value) + " makes " + what + " take " +
                          number_text(count) + " time steps; allowed: at most " +
                          number_text(max_time_steps) + " steps";
    // The count scales as 1/dt, so a key that sets dt in proportion runs from value * count / max on.
    if (std::isfinite(count))
        message += ", i.e. '" + key + "' >= " + number_text(value * count / max_time_steps);
    throw InputError(message);
}

} // namespace softgrain
