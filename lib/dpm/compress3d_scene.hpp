// dpm.compress3d scene (see compress3d_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_compress3d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> compress3d_parameters();

} // namespace softgrain::dpm
