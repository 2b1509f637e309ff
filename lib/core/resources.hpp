// Memory a run will need, estimated from its parameters before it allocates anything, so that an absurd
// size (particles = 1e9) is refused at once with exit 2 instead of running until the machine is out of
// memory. Estimates count the dominant storage only (a lower bound, never an inflated guess): a run that is
// refused could not have run.
#pragma once

#include <string>

namespace softgrain {

class Parameters;

struct MemoryEstimate
{
    double bytes = 0;
    std::string basis; // what was counted, naming the parameters: "particles x nodes = ... vertices at ..."
};

// `count` items of `bytes_each` bytes; `what` names the items and the parameters that set their number.
MemoryEstimate per_item_memory(double count, double bytes_each, const std::string& what);
// `matrices` dense n x n matrices of doubles (a Hessian, its eigenvectors); `what` names n's parameters.
MemoryEstimate dense_matrix_memory(double n, int matrices, const std::string& what);

// Bytes this process may still use: MemAvailable of /proc/meminfo, or the room left below the cgroup's
// memory.max when that is lower.
double available_memory_bytes();

// InputError (exit 2) naming the parameters (e.g. "particles = 1000000000, nodes = 16"), the estimate, its
// basis and the available memory when the run cannot fit.
void refuse_if_memory_exceeds(const MemoryEstimate& need, double available_bytes,
                              const std::string& parameters);

// "1.5 GiB": bytes for messages.
std::string memory_text(double bytes);

} // namespace softgrain
