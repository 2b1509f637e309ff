// dpm.slide3d scene (see slide3d_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_slide3d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> slide3d_parameters();

} // namespace softgrain::dpm
