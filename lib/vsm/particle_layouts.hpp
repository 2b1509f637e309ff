// Particle arrangements of the VSM scenes: cell-centred lattices, optionally jittered.
#pragma once

#include "core/rng.hpp"
#include "core/vector.hpp"

#include <array>

namespace softgrain::vsm {

// Cell-centred lattice of counts[0] x counts[1] x counts[2] particles filling the box [low, high]: particle
// (i, j, k) sits at the centre of its sub-box. With jitter > 0 every coordinate is displaced uniformly in
// [-jitter, jitter) times the sub-box size along that axis (jitter < 1/2 keeps each particle in its sub-box).
Points<3> jittered_lattice(const Vec3& low, const Vec3& high, const std::array<int, 3>& counts, double jitter,
                           Rng* rng);

} // namespace softgrain::vsm
