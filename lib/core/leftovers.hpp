#pragma once
// What a run creates and must not leave behind when a signal stops it: its partial result directory and
// its checkpoint lock file. The command line's signal watcher removes them (core/cli.cpp); leftovers of runs
// killed otherwise (SIGKILL) are removed by the next run into the same output directory.

#include <filesystem>

namespace softgrain {

// Registers a path that this run created and that a signal removes (a file, or a directory with its
// contents).
void remove_on_signal(const std::filesystem::path& path);

// The path is no longer this run's to remove: committed, handed over, or already removed.
void keep_on_signal(const std::filesystem::path& path);

// Removes every registered path; for the signal watcher, which exits right after.
void remove_leftovers_of_run_in_progress();

} // namespace softgrain
