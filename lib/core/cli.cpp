#include "core/cli.hpp"

#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/gsl_checked.hpp"
#include "core/leftovers.hpp"
#include "core/output.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <signal.h>
#include <thread>

#include <CLI/CLI.hpp>
#include <toml++/toml.h>

namespace softgrain {

namespace fs = std::filesystem;

namespace {

void list_scenes(const SceneRegistry& scenes)
{
    std::size_t width = 0;
    for (const auto& scene : scenes.all())
        width = std::max(width, scene.name.size());
    for (const auto& scene : scenes.all())
        std::cout << std::left << std::setw(static_cast<int>(width) + 2) << scene.name << scene.description
                  << "\n";
}

void describe_scene(const Scene& scene)
{
    // Columns as wide as their longest entry, plus two spaces.
    std::size_t name_width = std::string("parameter").size(), default_width = std::string("default").size(),
                unit_width = std::string("unit").size();
    for (const auto& p : scene.parameters) {
        name_width = std::max(name_width, p.name.size());
        default_width = std::max(default_width, to_string(p.default_value).size());
        unit_width = std::max(unit_width, p.unit.size());
    }
    const auto row = [&](const std::string& name, const std::string& value, const std::string& unit,
                         const std::string& meaning) {
        std::cout << std::left << std::setw(static_cast<int>(name_width + 2)) << name
                  << std::setw(static_cast<int>(default_width + 2)) << value
                  << std::setw(static_cast<int>(unit_width + 2)) << unit << meaning << "\n";
    };
    std::cout << scene.name << ": " << scene.description << "\n\n";
    row("parameter", "default", "unit", "meaning (allowed)");
    for (const auto& p : scene.parameters) {
        std::string old_names;
        for (const auto& old_name : p.old_names)
            old_names += (old_names.empty() ? "; deprecated name: " : ", ") + old_name;
        row(p.name, to_string(p.default_value), p.unit, p.description + " (" + p.allowed() + old_names + ")");
    }
}

// A scene to run: a registered name, or a TOML file naming its base scene with `scene = "..."`.
struct RunRequest
{
    const Scene* scene = nullptr;
    std::string output_name;
    Parameters parameters{{}};
};

RunRequest resolve_scene(const std::string& target, const SceneRegistry& scenes)
{
    const bool is_file = fs::path(target).extension() == ".toml";
    if (!is_file) {
        const Scene& scene = scenes.find(target);
        return {&scene, scene.name, Parameters(scene.parameters)};
    }
    if (!fs::is_regular_file(target)) throw InputError("scene file '" + target + "' does not exist");
    toml::table table;
    try {
        table = toml::parse_file(target);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError("scene file '" + target + "' is not valid TOML (line " + std::to_string(where.line) +
                         ", column " + std::to_string(where.column) + "): " + std::string(e.description()));
    }
    const auto base = table["scene"].value<std::string>();
    if (!base)
        throw InputError("scene file '" + target +
                         "': key 'scene' is missing or not a string; allowed: the name "
                         "of a scene from 'softgrain list', e.g. scene = \"core.harmonic\"");
    const Scene& scene = scenes.find(*base);
    RunRequest request{&scene, fs::path(target).stem().string(), Parameters(scene.parameters)};
    request.parameters.set_from_toml(table, target);
    return request;
}

void apply_overrides(Parameters& parameters, const std::vector<std::string>& assignments)
{
    for (const auto& assignment : assignments) {
        const auto equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0)
            throw InputError("--set '" + assignment + "' is not of the form key=value");
        parameters.set_from_text(assignment.substr(0, equals), assignment.substr(equals + 1));
    }
}

// How a run keeps checkpoints: `--checkpoint-every` seconds of wall time (absent: every 10 minutes for the
// scenes that write them), `--resume` from DIR/<name>.checkpoint if it exists.
struct CheckpointRequest
{
    std::optional<double> every_seconds;
    bool resume = false;
};

std::unique_ptr<Checkpoints> checkpoints_for(const Scene& scene, const RunRequest& request,
                                             const CheckpointRequest& asked, const fs::path& out_dir,
                                             const SceneRegistry& scenes)
{
    if (!scene.checkpoints) {
        if (!asked.every_seconds && !asked.resume) return nullptr;
        std::string allowed;
        for (const auto& s : scenes.all())
            if (s.checkpoints) allowed += (allowed.empty() ? "" : ", ") + s.name;
        throw InputError(std::string(asked.resume ? "--resume" : "--checkpoint-every") + ": scene '" +
                         scene.name + "' does not write checkpoints; allowed for: " + allowed);
    }
    const double every = asked.every_seconds.value_or(600.0);
    if (!(every >= 0) || !std::isfinite(every))
        throw InputError("--checkpoint-every " + std::to_string(every) +
                         ": allowed: seconds of wall time between checkpoints, >= 0 (0: none)");
    const fs::path file = out_dir / (request.output_name + ".checkpoint");
    if (asked.resume && !fs::exists(file))
        std::cerr << "softgrain: no checkpoint " << file.string() << ": starting from the beginning\n";
    return std::make_unique<Checkpoints>(file, every, asked.resume, scene.name,
                                         request.parameters.to_json().dump(), software_version());
}

// A run whose memory estimate exceeds what the machine has is refused before it starts (exit 2); the message
// names the parameters the estimate counts, with their values.
void refuse_absurd_size(const Scene& scene, const Parameters& parameters)
{
    const MemoryEstimate need = scene.memory(parameters);
    const nlohmann::json values = parameters.to_json();
    std::string named;
    for (const auto& spec : scene.parameters)
        if (std::regex_search(need.basis, std::regex("\\b" + spec.name + "\\b")))
            named += (named.empty() ? "" : ", ") + spec.name + " = " + values[spec.name].dump();
    refuse_if_memory_exceeds(need, available_memory_bytes(), named);
}

// A ParaView time series: `--vtk`, with `--vtk-every N` every N-th of the scene's frames.
struct VtkRequest
{
    bool enabled = false;
    std::optional<std::int64_t> every;
};

void check_vtk_request(const Scene& scene, const VtkRequest& asked, const SceneRegistry& scenes)
{
    if (asked.every && *asked.every < 1)
        throw InputError(
            "--vtk-every " + std::to_string(*asked.every) +
            ": allowed: an integer >= 1 (every N-th of the scene's frames: recorded states or load steps)");
    if (asked.every && !asked.enabled)
        throw InputError("--vtk-every " + std::to_string(*asked.every) +
                         " without --vtk; allowed: --vtk --vtk-every N, or neither");
    if (!asked.enabled || scene.vtk) return;
    std::string allowed;
    for (const auto& s : scenes.all())
        if (s.vtk) allowed += (allowed.empty() ? "" : ", ") + s.name;
    const std::string why = scene.no_vtk_reason.empty() ? " yet" : ": " + scene.no_vtk_reason;
    throw InputError("--vtk: scene '" + scene.name + "' writes no VTK frames" + why +
                     "; allowed for: " + allowed);
}

// Every rank of an MPI run runs the scene (ensembles spread their members over the ranks, core/ensemble.hpp)
// and only the first writes: the others get no checkpoints, no frames and a context that discards its
// output. A failure of any rank, up to the end of the scene, is every rank's before anything is committed.
int run_scene(const std::string& target, const std::vector<std::string>& assignments,
              const std::string& out_dir, bool quiet, const CheckpointRequest& checkpointing,
              const VtkRequest& vtk, const SceneRegistry& scenes)
{
    RunRequest request;
    std::unique_ptr<RunContext> context;
    on_every_rank([&] {
        request = resolve_scene(target, scenes);
        apply_overrides(request.parameters, assignments);
        check_vtk_request(*request.scene, vtk, scenes);
        if (request.scene->memory) refuse_absurd_size(*request.scene, request.parameters);
        const bool writes = first_rank();
        auto checkpoints =
            writes ? checkpoints_for(*request.scene, request, checkpointing, out_dir, scenes) : nullptr;
        context = std::make_unique<RunContext>(out_dir, request.output_name, request.parameters, quiet,
                                               writes ? RunContext::Output::written
                                                      : RunContext::Output::discarded);
        context->enable_checkpoints(std::move(checkpoints));
        if (vtk.enabled) context->enable_vtk(vtk.every);
        request.scene->run(request.parameters, *context);
    });
    const fs::path written = context->commit();
    if (!quiet) std::cout << "wrote " << written.string() << "\n";
    return exit_success;
}

// `advise`: per method, the cheapest run of the scene's stored sweep within the tolerance, and the cheapest
// of all (issue 22: model no more than a scene needs).
void advise_scene(const SceneRegistry& scenes, const std::string& name, double tolerance,
                  const std::optional<fs::path>& given)
{
    const Scene& scene = scenes.find(name);
    if (!scene.sweep) {
        std::string advised;
        for (const Scene& s : scenes.all())
            if (s.sweep) advised += (advised.empty() ? "" : ", ") + s.name;
        throw InputError("scene '" + name +
                         "' has no stored work-precision sweep to advise from; allowed: " + advised);
    }
    const SweepTable& table = *scene.sweep;
    const fs::path file = locate_sweep(table, given);
    const Advice advice = advise(read_sweep(file, table), tolerance);
    const std::string scale = sweep_scale(file);
    std::cout << "sweep: " << file.string() << (scale.empty() ? "" : " (scale " + scale + ")") << "\n"
              << "error: " << table.error_meaning << "\n"
              << "resolution: " << table.resolution_meaning << "\n"
              << "cost: wall time of one run where the sweep was made (it ranks, it does not predict)\n";
    for (const Advice::PerMethod& m : advice.methods) {
        std::cout << m.run.method << ": ";
        if (m.met)
            std::cout << "cheapest within " << tolerance << ": resolution " << m.run.resolution << ", error "
                      << m.run.error << ", " << m.run.cost_s << " s\n";
        else
            std::cout << "no run within " << tolerance << "; its smallest error is " << m.run.error
                      << " at resolution " << m.run.resolution << " (" << m.run.cost_s << " s)\n";
    }
    if (advice.recommended) {
        std::cout << "recommended_method = " << advice.recommended->method << "\n"
                  << "recommended_resolution = " << advice.recommended->resolution << "\n"
                  << "recommended_cost_s = " << advice.recommended->cost_s << "\n";
    } else {
        std::cout << "recommended_method = none (no run of the sweep is within " << tolerance
                  << "; a finer sweep, at a larger scale of its figure, may be)\n";
    }
}

// A run stopped by SIGINT, SIGTERM or SIGHUP removes its partial directory and its checkpoint lock before it
// exits with 128 + the signal's number. The signals are blocked in every thread (OpenMP's threads inherit the
// mask) and taken by one watcher thread with sigwait, where removing a directory is safe, as it is not in a
// handler.
void remove_partial_output_on_signal()
{
    static sigset_t stopping;
    sigemptyset(&stopping);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP})
        sigaddset(&stopping, signal);
    pthread_sigmask(SIG_BLOCK, &stopping, nullptr);
    std::thread([] {
        int signal = 0;
        sigwait(&stopping, &signal);
        remove_leftovers_of_run_in_progress();
        std::_Exit(128 + signal);
    }).detach();
}

} // namespace

int run_command_line(int argc, char** argv, const SceneRegistry& scenes)
{
    use_status_codes_for_gsl_errors();
    CLI::App app{"softgrain: particles with shape degrees of freedom (SPD, DPM, VSM, SD)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", software_version());

    auto* list =
        app.add_subcommand("list", "every named scene, one per line: name, then a one-line description");

    std::string describe_name;
    auto* describe = app.add_subcommand("describe", "a scene's parameters: name, default, unit, meaning");
    describe->add_option("scene", describe_name, "scene name")->required();

    std::string run_target, out_dir = "out";
    std::vector<std::string> assignments;
    bool quiet = false;
    auto* run = app.add_subcommand("run", "run a named scene or a TOML scene file");
    run->add_option("scene", run_target, "scene name or file.toml")->required();
    run->add_option("--set", assignments, "override a parameter: key=value (repeatable)")->take_all();
    run->add_option("--out", out_dir, "output directory; results go to DIR/<scene>/")->capture_default_str();
    run->add_flag("--quiet", quiet, "no progress or messages on success");
    CheckpointRequest checkpointing;
    run->add_option("--checkpoint-every", checkpointing.every_seconds,
                    "seconds of wall time between checkpoints DIR/<scene>.checkpoint of a long run (default "
                    "600; 0: none)");
    run->add_flag("--resume", checkpointing.resume,
                  "continue from DIR/<scene>.checkpoint (bit-for-bit) if it exists, else start afresh");

    VtkRequest vtk;
    run->add_flag("--vtk", vtk.enabled,
                  "write a ParaView time series DIR/<scene>/vtk/<scene>.pvd with one .vtp file per dataset "
                  "and frame");
    run->add_option(
        "--vtk-every", vtk.every,
        "with --vtk: keep every N-th of the scene's frames (its recorded states or load steps; default 1)");

    std::string advise_name;
    double tolerance = 0;
    std::optional<fs::path> sweep_file;
    auto* advise_command = app.add_subcommand(
        "advise", "the cheapest method and resolution of a scene within an error tolerance, from its stored "
                  "work-precision sweep");
    advise_command->add_option("scene", advise_name, "scene name")->required();
    advise_command
        ->add_option("--tolerance", tolerance, "largest acceptable error, in the sweep's error measure (> 0)")
        ->required()
        ->check(CLI::PositiveNumber);
    advise_command->add_option("--sweep", sweep_file,
                               "work-precision table to read (default: figures/<paper>/<figure>.dat, else "
                               "data/<paper>/<figure>.dat)");

    // The ranks of an MPI run other than the first print nothing: the first prints for all of them (an error
    // of any rank reaches it, core/ensemble.hpp).
    if (!first_rank()) {
        std::cout.setstate(std::ios::badbit);
        std::cerr.setstate(std::ios::badbit);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? exit_success : exit_bad_input;
    }

    try {
        if (*list)
            list_scenes(scenes);
        else if (*describe)
            describe_scene(scenes.find(describe_name));
        else if (*advise_command)
            advise_scene(scenes, advise_name, tolerance, sweep_file);
        else if (*run) {
            remove_partial_output_on_signal();
            return run_scene(run_target, assignments, out_dir, quiet, checkpointing, vtk, scenes);
        }
        return exit_success;
    } catch (...) {
        const Failure failure = failure_of(std::current_exception());
        std::cerr << "softgrain: " << user_message(failure) << "\n";
        return exit_code(failure);
    }
}

} // namespace softgrain
