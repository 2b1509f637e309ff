// Errors that reach the user through the command line.
//
// InputError     -> exit code 2: bad input. The message names the key, the value and what is allowed.
// NumericalError -> exit code 3: numerical trouble. The message names the quantity, the step and the
//                   likely cause (e.g. a time step above the stability limit).
// IoError        -> exit code 4: the machine refused: a file or directory that cannot be written (the path
//                   and the system's reason), a full disk; std::bad_alloc and std::filesystem errors
//                   map here.
// anything else  -> exit code 5: an internal error (a defect of softgrain, to be reported).
// In every case the run's partial output directory is removed: nothing half-written is left behind.
#pragma once

#include <cstdint>
#include <sstream>
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

struct IoError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// A number as messages show it: `digits` significant digits, "inf" and "nan" spelled out (std::to_string
// shows 1e-300 as 0.000000).
inline std::string number_text(double value, int digits = 6)
{
    std::ostringstream out;
    out.precision(digits);
    out << value;
    return out.str();
}

inline constexpr int exit_success = 0;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_numerical_failure = 3;
inline constexpr int exit_io_failure = 4;
inline constexpr int exit_internal_error = 5;

} // namespace softgrain
