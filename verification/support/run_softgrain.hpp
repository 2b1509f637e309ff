// Runs the `softgrain` executable built with the tests, for checks of the command-line contract (exit codes,
// messages) that a library call cannot see.
#pragma once

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <sys/wait.h>

namespace softgrain::verification {

struct Outcome
{
    int exit_code;      // -1 if the process did not exit normally
    std::string output; // stdout and stderr
};

// A shell command line (sh -c); stderr is merged into the output.
inline Outcome run_shell(const std::string& command_line)
{
    const std::string command = "{ " + command_line + "; } 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot start: " + command);
    std::string output;
    std::array<char, 4096> buffer{};
    while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe))
        output += buffer.data();
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// `arguments` follow the executable on a shell command line; stderr is merged into the output.
inline Outcome run_softgrain(const std::string& arguments)
{
    return run_shell(std::string(SOFTGRAIN_EXECUTABLE) + " " + arguments);
}

} // namespace softgrain::verification
