// dpm.jam scene (see jam_scene.cpp).
#pragma once

#include "core/parameters.hpp"
#include "dpm/jam.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_jam(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> jam_parameters();
// dpm.jam's: jam_parameters() and `decompress`.
std::vector<ParameterSpec> jam_scene_parameters();
// The jamming protocol's options from the parameters of jam_parameters() (also dpm.shear_modulus's).
JamOptions jam_options(const Parameters& p);

} // namespace softgrain::dpm
