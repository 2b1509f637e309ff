// dpm.shear_modulus scene (see shear_modulus_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_shear_modulus(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> shear_modulus_parameters();

} // namespace softgrain::dpm
