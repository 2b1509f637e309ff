// dpm.shear_friction scene (see shear_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_shear_friction(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> shear_friction_parameters();

} // namespace softgrain::dpm
