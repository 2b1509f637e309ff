// dpm.shear_modulus3d scene (see shear_modulus3d_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_shear_modulus3d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> shear_modulus3d_parameters();

} // namespace softgrain::dpm
