// dpm.modes scene (see modes_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_modes(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> modes_parameters();

} // namespace softgrain::dpm
