// dpm.jam scene (see jam_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_jam(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> jam_parameters();

} // namespace softgrain::dpm
