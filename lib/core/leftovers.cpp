#include "core/leftovers.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

namespace softgrain {

namespace fs = std::filesystem;

namespace {
std::mutex leftovers_mutex;
std::vector<fs::path> leftovers;
} // namespace

void remove_on_signal(const fs::path& path)
{
    const std::lock_guard lock(leftovers_mutex);
    leftovers.push_back(path);
}

void keep_on_signal(const fs::path& path)
{
    const std::lock_guard lock(leftovers_mutex);
    leftovers.erase(std::remove(leftovers.begin(), leftovers.end(), path), leftovers.end());
}

void remove_leftovers_of_run_in_progress()
{
    const std::lock_guard lock(leftovers_mutex);
    std::error_code ignored;
    for (const fs::path& path : leftovers)
        fs::remove_all(path, ignored);
}

} // namespace softgrain
