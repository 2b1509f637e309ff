// Errors that reach the user through the command line.
//
// InputError     -> exit code 2: bad input. The message names the key, the value and what is allowed.
// NumericalError -> exit code 3: numerical trouble. The message names the quantity, the step and the
//                   likely cause (e.g. a time step above the stability limit).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace softgrain {

struct InputError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct NumericalError : std::runtime_error
{
    NumericalError(const std::string& what_failed, std::int64_t at_step, const std::string& likely_cause)
        : std::runtime_error("numerical failure: " + what_failed + " at step " + std::to_string(at_step) +
                             "; likely cause: " + likely_cause),
          quantity(what_failed), step(at_step)
    {
    }
    std::string quantity;
    std::int64_t step;
};

inline constexpr int exit_success = 0;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_numerical_failure = 3;

} // namespace softgrain
