// The `softgrain` command line: list, describe, run. Returns the process exit code
// (0 success, 2 bad input, 3 numerical failure).
#pragma once

#include "core/scene.hpp"

namespace softgrain {

int run_command_line(int argc, char** argv, const SceneRegistry& scenes);

} // namespace softgrain
