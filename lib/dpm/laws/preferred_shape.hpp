// The preferred shape parameter A0 = (sum_i l_i0)^2/(4 pi a0) of a scene (DPM sec. 9.2), read from a real
// parameter that also accepts the keyword `min` (OptionBinding::real_or_keyword): the minimum
// A_min(N) = N tan(pi/N)/pi of an N-gon, which depends on the run's vertex count and so cannot be a fixed
// default.
#pragma once

#include <optional>

namespace softgrain::dpm {

// A0 for a particle of `nodes` vertices: A_min(nodes) for nothing (the keyword `min`), else the number, which
// must be >= A_min (InputError naming A0 otherwise: no polygon of N vertices has a smaller
// shape parameter).
double preferred_shape_parameter(std::optional<double> A0, int nodes);

} // namespace softgrain::dpm
