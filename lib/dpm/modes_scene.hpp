// dpm.modes scene (see modes_scene.cpp).
#pragma once

#include "core/parameters.hpp"

#include <nlohmann/json.hpp>
#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_modes(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> modes_parameters();

// Median of the values that are not NaN, null when there is none (summary keys of dpm.modes, dpm.modes3d).
nlohmann::json median_or_null(std::vector<double> values);

} // namespace softgrain::dpm
