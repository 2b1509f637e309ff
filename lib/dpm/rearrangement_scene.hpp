// dpm.rearrangement scene (see rearrangement_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_rearrangement(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> rearrangement_parameters();

} // namespace softgrain::dpm
