// `softgrain advise <scene> --tolerance T`: which method and which resolution of a scene meet an error
// tolerance at the least cost, answered from a stored work-precision sweep (the table that a reproduction
// figure writes, one row per run: method, resolution, error against the scene's reference, wall time),
// without rerunning it. "Model no more than a scene needs" (issue 22): the cheapest run whose error is within
// T.
//
// The costs are the wall times of the machine and the invocation that made the sweep (runs side by side under
// make -j2 on a shared machine): they rank methods and resolutions, they do not predict another machine.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace softgrain {

// How a scene's work-precision table is read: the reproduction figure that writes it and its columns.
struct SweepTable
{
    std::string paper;                // reproductions/<paper>/manifest.toml
    std::string figure;               // the figure id: its table is <paper>/<figure>.dat
    std::string method_column;        // integer code of the method, 0, 1, ...
    std::vector<std::string> methods; // method names by code
    std::string variant_column;     // a parameter that splits a method into curves (e.g. dt_factor); "" none
    std::string variant_method;     // the method it splits (the others ignore that parameter)
    std::string resolution_column;  // e.g. nodes
    std::string resolution_meaning; // e.g. "vertices N of the ring"
    std::string error_column;       // the error of a run against the scene's reference
    std::string error_meaning;
    std::string cost_column = "wall_time_s"; // [s]
};

// One run of the sweep, as the advice reads it.
struct SweepRun
{
    std::string method; // name, with the variant when the table has one: "spd (dt_factor 0.5)"
    double resolution = 0, error = 0, cost_s = 0;
};

struct Advice
{
    // Per method (in order of first appearance): its cheapest run within the tolerance, or, when none is,
    // its most accurate run (met = false).
    struct PerMethod
    {
        SweepRun run;
        bool met = false;
    };
    std::vector<PerMethod> methods;
    std::optional<SweepRun> recommended; // the cheapest run within the tolerance over all methods
};

// The runs of a stored sweep table (the format of scripts/reproduce: '#' comment lines, a line of column
// names, one line of numbers per run). Throws InputError naming the file and the missing column or bad line.
std::vector<SweepRun> read_sweep(const std::filesystem::path& file, const SweepTable& table);

// The scale the table was made at ("smoke", "default", "paper"), from its generator line; "" if unstated.
std::string sweep_scale(const std::filesystem::path& file);

// Runs with a non-finite error or cost (a run that stopped with a diagnosis) meet no tolerance.
Advice advise(const std::vector<SweepRun>& runs, double tolerance);

// Where the sweep of `table` is looked for, in order: the given file, else figures/<paper>/<figure>.dat (the
// output of `make reproduce-figures` in this directory), else data/<paper>/<figure>.dat (the sweep stored in
// the checkout). Throws InputError naming the places and the command that makes one when none exists.
std::filesystem::path locate_sweep(const SweepTable& table,
                                   const std::optional<std::filesystem::path>& given);

} // namespace softgrain
