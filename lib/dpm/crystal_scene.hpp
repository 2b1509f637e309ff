// dpm.crystal_modes scene (see crystal_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_crystal_modes(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> crystal_modes_parameters();

} // namespace softgrain::dpm
