// Comparison of a computed value with a reference under a stated tolerance.
//
// doctest's Approx is nearly absolute for small numbers; verification uses this helper instead, which
// takes a relative and an absolute tolerance (|x - ref| <= rel |ref| + abs) and prints both numbers and
// the relative error when it fails. Two kinds of tolerance, never mixed in one check:
//   * analytic: from the discretisation order, the step size or the paper's own agreement (say which);
//   * round-off: a multiple of machine epsilon, written as `n * round_off`.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace softgrain::verification {

inline constexpr double round_off = std::numeric_limits<double>::epsilon();

struct Tolerance
{
    double relative = 0;
    double absolute = 0;
};

inline std::string describe_comparison(double value, double reference, Tolerance tolerance)
{
    std::ostringstream out;
    out.precision(10);
    out << "value " << value << " vs reference " << reference << " (relative error "
        << (reference != 0 ? std::abs(value - reference) / std::abs(reference) : std::abs(value - reference))
        << "; allowed rel " << tolerance.relative << ", abs " << tolerance.absolute << ")";
    return out.str();
}

inline bool within(double value, double reference, Tolerance tolerance)
{
    return std::isfinite(value) &&
           std::abs(value - reference) <= tolerance.relative * std::abs(reference) + tolerance.absolute;
}

} // namespace softgrain::verification

// CHECK_CLOSE(value, reference, Tolerance{rel, abs}): fails with both numbers and the relative error.
#define CHECK_CLOSE(value, reference, tolerance)                                                             \
    do {                                                                                                     \
        const double sg_value_ = (value), sg_reference_ = (reference);                                       \
        INFO(::softgrain::verification::describe_comparison(sg_value_, sg_reference_, (tolerance)));         \
        CHECK(::softgrain::verification::within(sg_value_, sg_reference_, (tolerance)));                     \
    } while (false)
