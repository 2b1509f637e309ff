// dpm.shape3d and dpm.modes3d scenes (see scenes3d.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_shape3d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> shape3d_parameters();

void run_modes3d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> modes3d_parameters();

} // namespace softgrain::dpm
