// dpm.packing_fraction scene (see packing_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_packing_fraction(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> packing_fraction_parameters();

} // namespace softgrain::dpm
