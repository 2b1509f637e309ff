// dpm.bench scene (see bench_scene.cpp).
#pragma once

#include "core/parameters.hpp"
#include "core/resources.hpp"

#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

void run_bench(const Parameters& p, RunContext& context);
// dpm.jam's jam_parameters() and `dimension`.
std::vector<ParameterSpec> bench_parameters();
// The dense spectrum of the jammed packing: two n x n matrices, n = dimension x vertices.
MemoryEstimate bench_memory(const Parameters& p);

} // namespace softgrain::dpm
