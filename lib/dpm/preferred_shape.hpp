// The preferred shape parameter A0 = (sum_i l_i0)^2/(4 pi a0) of a scene (DPM sec. 9.2), read from a real
// parameter that also accepts the keyword `min`: the minimum A_min(N) = N tan(pi/N)/pi of an N-gon, which
// depends on the run's vertex count and so cannot be a fixed default.
#pragma once

#include "core/parameters.hpp"

#include <string>

namespace softgrain::dpm {

// The spec: a real >= 1 (A_min(N) > 1 for every N) or `min`; `min` is the default when default_min.
ParameterSpec preferred_shape_parameter_spec(double default_value, bool default_min, std::string description);

// A0 for a particle of `nodes` vertices: A_min(nodes) for `min`, else the number, which must be >= A_min
// (InputError otherwise: no polygon of N vertices has a smaller shape parameter).
double preferred_shape_parameter(const Parameters& p, const std::string& name, int nodes);

} // namespace softgrain::dpm
