// dpm.compress_box scene (see box_compress_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_compress_box(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> compress_box_parameters();

} // namespace softgrain::dpm
