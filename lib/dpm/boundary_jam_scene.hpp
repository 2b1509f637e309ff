// dpm.boundary_jam scene (see boundary_jam_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_boundary_jam(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> boundary_jam_parameters();

} // namespace softgrain::dpm
