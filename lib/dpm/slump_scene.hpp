// dpm.slump scene (see slump_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_slump_scene(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> slump_parameters();

} // namespace softgrain::dpm
