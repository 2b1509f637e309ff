// How many time steps a protocol takes, checked before the loop that takes them.
//
// A protocol derives its step counts from a duration over its time step (a load step, a relaxation budget,
// a pull to the final strain). A time step the user made absurdly small (dt_factor = 1e-310) turns such a
// count into 1e300 or inf, which no counter holds (the conversion to an integer is undefined) and no run
// finishes: it is refused as bad input before the run starts, naming the parameter that set the step.
#pragma once

#include <string>

namespace softgrain {

// Most time steps one loop of a protocol may take: 1e12 steps are weeks of CPU time even for one particle.
inline constexpr double max_time_steps = 1e12;

// `count` time steps (already rounded as the protocol wants; `what` they are for, e.g. "one load step"),
// as a counter. A count that is not finite or above max_time_steps throws InputError naming the parameter
// that set the time step (`key` = `value`), the count and the smallest value of the key that runs.
long checked_step_count(double count, const std::string& what, const std::string& key, double value);

} // namespace softgrain
