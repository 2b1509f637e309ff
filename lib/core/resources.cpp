#include "core/resources.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace softgrain {

MemoryEstimate per_item_memory(double count, double bytes_each, const std::string& what)
{
    return {count * bytes_each,
            what + " = " + number_text(count) + " at " + memory_text(bytes_each) + " each"};
}

MemoryEstimate dense_matrix_memory(double n, int matrices, const std::string& what)
{
    return {matrices * n * n * sizeof(double), std::to_string(matrices) +
                                                   " dense n x n matrices of doubles, n = " + what + " = " +
                                                   number_text(n)};
}

namespace {

// A number of bytes from a line "Key:   123 kB" of /proc/meminfo, or infinity when the key is absent.
double meminfo_bytes(const std::string& key)
{
    std::ifstream meminfo("/proc/meminfo");
    std::string name, unit;
    double value = 0;
    while (meminfo >> name >> value) {
        std::getline(meminfo, unit);
        if (name == key + ":") return value * 1024.0; // the kernel writes kB and means KiB
    }
    return std::numeric_limits<double>::infinity();
}

// Room left under cgroup v2's memory.max ("max": no limit), or infinity.
double cgroup_room_bytes()
{
    std::ifstream max_file("/sys/fs/cgroup/memory.max"), current_file("/sys/fs/cgroup/memory.current");
    std::string max_text;
    double current = 0;
    if (!(max_file >> max_text) || max_text == "max" || !(current_file >> current))
        return std::numeric_limits<double>::infinity();
    return std::stod(max_text) - current;
}

} // namespace

double available_memory_bytes()
{
    return std::min(meminfo_bytes("MemAvailable"), cgroup_room_bytes());
}

void refuse_if_memory_exceeds(const MemoryEstimate& need, double available_bytes,
                              const std::string& parameters)
{
    if (need.bytes <= available_bytes) return;
    throw InputError(parameters + ": the run needs at least " + memory_text(need.bytes) + " of memory (" +
                     need.basis + "), and this machine has " + memory_text(available_bytes) +
                     " available; allowed: sizes whose estimate fits in the available memory");
}

std::string memory_text(double bytes)
{
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int unit = 0;
    while (std::abs(bytes) >= 1024.0 && unit < 6) {
        bytes /= 1024.0;
        ++unit;
    }
    return number_text(bytes, 3) + " " + units[unit];
}

} // namespace softgrain
