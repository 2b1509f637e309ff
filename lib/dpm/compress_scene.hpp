// dpm.compress2d scene (see compress_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_compress2d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> compress2d_parameters();

} // namespace softgrain::dpm
