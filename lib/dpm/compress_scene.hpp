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

// The compression scenes report a force-displacement exponent from three samples on: two fit any power law
// exactly, so they would report a number that nothing checks.
constexpr std::size_t minimum_exponent_points = 3;

void run_compress2d(const Parameters& p, RunContext& context);
std::vector<ParameterSpec> compress2d_parameters();

} // namespace softgrain::dpm
