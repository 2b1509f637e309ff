// The `softgrain` command-line contract (DESIGN.md): list, describe, run; exit codes 0 / 2 / 3; bad input
// names the key, the value and what is allowed; nothing half-written is left behind.
#include "core/output.hpp"
#include "core/scene.hpp"
#include "support/run_softgrain.hpp"
#include "support/tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using softgrain::verification::Outcome;
using softgrain::verification::run_softgrain;

fs::path scratch_directory(const std::string& name)
{
    const fs::path dir =
        fs::temp_directory_path() / ("softgrain-cli-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write_file(const fs::path& path, const std::string& text)
{
    std::ofstream(path) << text;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("softgrain list names every registered scene, and describe works for each")
{
    const Outcome list = run_softgrain("list");
    CHECK(list.exit_code == 0);
    const softgrain::SceneRegistry scenes = softgrain::all_scenes();
    for (const auto& scene : scenes.all()) {
        CAPTURE(scene.name);
        CHECK(contains(list.output, scene.name + " "));
        const Outcome describe = run_softgrain("describe " + scene.name);
        CHECK(describe.exit_code == 0);
        for (const auto& parameter : scene.parameters)
            CHECK(contains(describe.output, parameter.name));
    }
}

TEST_CASE("bad input exits with code 2 and names the key, the value and what is allowed")
{
    const fs::path dir = scratch_directory("bad");
    const std::string out = " --out " + dir.string();

    const Outcome unknown_key = run_softgrain("run core.harmonic --set viscosity=1" + out);
    CHECK(unknown_key.exit_code == 2);
    CHECK(contains(unknown_key.output, "'viscosity'"));
    CHECK(contains(unknown_key.output, "allowed: mass, stiffness, dt, periods"));

    const Outcome wrong_type = run_softgrain("run core.harmonic --set dt=fast" + out);
    CHECK(wrong_type.exit_code == 2);
    CHECK(contains(wrong_type.output, "'dt' = 'fast'"));
    CHECK(contains(wrong_type.output, "a real number > 0"));

    const Outcome negative_stiffness = run_softgrain("run core.harmonic --set stiffness=-5" + out);
    CHECK(negative_stiffness.exit_code == 2);
    CHECK(contains(negative_stiffness.output, "'stiffness' = '-5' is out of range"));
    CHECK(contains(negative_stiffness.output, "> 0 [N/m]"));

    const Outcome infinite = run_softgrain("run core.harmonic --set mass=inf" + out);
    CHECK(infinite.exit_code == 2);
    CHECK(contains(infinite.output, "'mass' = 'inf'"));

    const Outcome unknown_scene = run_softgrain("run core.nothing" + out);
    CHECK(unknown_scene.exit_code == 2);
    CHECK(contains(unknown_scene.output, "'core.nothing'"));

    const Outcome missing_file = run_softgrain("run " + (dir / "absent.toml").string() + out);
    CHECK(missing_file.exit_code == 2);
    CHECK(contains(missing_file.output, "absent.toml"));

    write_file(dir / "malformed.toml", "scene = \"core.harmonic\"\nmass = = 3\n");
    const Outcome malformed = run_softgrain("run " + (dir / "malformed.toml").string() + out);
    CHECK(malformed.exit_code == 2);
    CHECK(contains(malformed.output, "malformed.toml"));
    CHECK(contains(malformed.output, "line 2"));

    write_file(dir / "wrongtype.toml", "scene = \"core.harmonic\"\nperiods = \"many\"\n");
    const Outcome toml_type = run_softgrain("run " + (dir / "wrongtype.toml").string() + out);
    CHECK(toml_type.exit_code == 2);
    CHECK(contains(toml_type.output, "'periods'"));

    const Outcome no_assignment = run_softgrain("run core.harmonic --set dt" + out);
    CHECK(no_assignment.exit_code == 2);

    const Outcome unknown_option = run_softgrain("run core.harmonic --speed" + out);
    CHECK(unknown_option.exit_code == 2);

    // None of these left an output directory behind.
    CHECK_FALSE(fs::exists(dir / "core.harmonic"));
    CHECK_FALSE(fs::exists(dir / "malformed"));
    fs::remove_all(dir);
}

TEST_CASE("run writes summary.json and self-describing tables; a TOML scene file takes the same keys")
{
    const fs::path dir = scratch_directory("run");
    const Outcome run =
        run_softgrain("run core.harmonic --quiet --set dt=0.002 --set periods=5 --out " + dir.string());
    REQUIRE(run.exit_code == 0);
    CHECK(run.output.empty()); // --quiet
    const auto summary = nlohmann::json::parse(std::ifstream(dir / "core.harmonic" / "summary.json"));
    for (const char* key : {"period", "period_theory", "energy_error_max", "parameters", "software_version",
                            "wall_time_s", "time_per_step_s", "peak_memory_mib"})
        CHECK(summary.contains(key));
    CHECK(summary["parameters"]["dt"] == 0.002);
    std::ifstream table(dir / "core.harmonic" / "trajectory.dat");
    std::string line, header;
    while (std::getline(table, line) && line.rfind('#', 0) == 0)
        CHECK(!line.empty());
    header = line;
    CHECK(header == "t x v energy_error");

    write_file(dir / "slow.toml", "scene = \"core.harmonic\"\ndt = 0.004\nperiods = 3\nstiffness = 25\n");
    const Outcome file_run =
        run_softgrain("run " + (dir / "slow.toml").string() + " --quiet --out " + dir.string());
    REQUIRE(file_run.exit_code == 0);
    const auto file_summary = nlohmann::json::parse(std::ifstream(dir / "slow" / "summary.json"));
    CHECK(file_summary["parameters"]["stiffness"] == 25.0);
    CHECK(file_summary["parameters"]["dt"] == 0.004);
    fs::remove_all(dir);
}

TEST_CASE("a time step above the stability limit exits with code 3, names the limit and leaves no output")
{
    const fs::path dir = scratch_directory("unstable");
    const Outcome run = run_softgrain("run core.harmonic --set dt=0.3 --out " + dir.string()); // dt_c = 0.2 s
    CHECK(run.exit_code == 3);
    CHECK(contains(run.output, "stability limit"));
    CHECK(contains(run.output, "at step"));
    CHECK(fs::is_empty(dir)); // neither the scene directory nor a partial one
    fs::remove_all(dir);
}

TEST_CASE("an --out that cannot be written exits with code 4, names the path and leaves nothing behind")
{
    const fs::path dir = scratch_directory("unwritable");
    write_file(dir / "plain", "not a directory\n");
    const Outcome run = run_softgrain("run core.harmonic --quiet --out " + (dir / "plain").string());
    CHECK(run.exit_code == 4);
    CHECK(contains(run.output, "I/O failure"));
    CHECK(contains(run.output, (dir / "plain").string()));
    CHECK(fs::is_regular_file(dir / "plain"));
    fs::remove_all(dir);
}

TEST_CASE("a run never deletes what it did not create: a file or foreign directory where its result goes")
{
    const fs::path dir = scratch_directory("foreign");
    write_file(dir / "core.harmonic", "the user's notes\n");
    const Outcome over_file = run_softgrain("run core.harmonic --quiet --out " + dir.string());
    CHECK(over_file.exit_code == 4);
    CHECK(contains(over_file.output, "not the result of a softgrain run"));
    CHECK(fs::is_regular_file(dir / "core.harmonic"));

    fs::remove(dir / "core.harmonic");
    fs::create_directories(dir / "core.harmonic");
    write_file(dir / "core.harmonic" / "data.txt", "the user's data\n");
    const Outcome over_directory = run_softgrain("run core.harmonic --quiet --out " + dir.string());
    CHECK(over_directory.exit_code == 4);
    CHECK(fs::is_regular_file(dir / "core.harmonic" / "data.txt"));
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1); // no partial directory

    // A softgrain result (it has summary.json) is replaced by the next run of the same scene.
    fs::remove_all(dir / "core.harmonic");
    REQUIRE(run_softgrain("run core.harmonic --quiet --out " + dir.string()).exit_code == 0);
    CHECK(run_softgrain("run core.harmonic --quiet --set periods=2 --out " + dir.string()).exit_code == 0);
    const auto summary = nlohmann::json::parse(std::ifstream(dir / "core.harmonic" / "summary.json"));
    CHECK(summary["parameters"]["periods"] == 2);
    fs::remove_all(dir);
}

TEST_CASE("identical runs finishing into the same --out at once all succeed; the last complete one stays")
{
    const fs::path dir = scratch_directory("concurrent");
    const std::string run = std::string(SOFTGRAIN_EXECUTABLE) +
                            " run core.harmonic --quiet --set periods=2 --out " + dir.string();
    // 20 pairs: before the result was moved aside under a name of its own, 11 of 40 pairs had one run abort.
    const std::string pairs = "for k in $(seq 20); do " + run + " & a=$!; " + run +
                              " & b=$!; wait $a || echo FAILED; wait $b || echo FAILED; done";
    const Outcome outcome = softgrain::verification::run_shell(pairs);
    CHECK(outcome.exit_code == 0);
    CHECK_FALSE(contains(outcome.output, "FAILED"));
    CHECK(fs::is_regular_file(dir / "core.harmonic" / "summary.json"));
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1); // nothing left aside
    fs::remove_all(dir);
}

TEST_CASE("a GSL error is a diagnosed numerical failure (exit 3), never GSL's abort")
{
    const fs::path dir = scratch_directory("gsl");
    // h0 = 1e308: the force balance of eq. (1) meets a non-finite function value in GSL's Brent solver, whose
    // default handler aborted the process (exit 134) and left the partial directory behind.
    const Outcome run = run_softgrain("run sd.approach --quiet --set h0=1e308 --out " + dir.string());
    CHECK(run.exit_code == 3);
    CHECK(contains(run.output, "numerical failure"));
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("a run that cannot take the steps it is asked for is refused (exit 2), never exits 0 with nonsense")
{
    const fs::path dir = scratch_directory("steps");
    const std::string out = " --quiet --out " + dir.string();
    const Outcome tiny_dt = run_softgrain("run core.harmonic --set dt=1e-300" + out); // the count overflowed
    CHECK(tiny_dt.exit_code == 2);
    CHECK(contains(tiny_dt.output, "steps; allowed: 1 to 1e10 steps"));
    const Outcome tiny_mass =
        run_softgrain("run core.harmonic --set mass=1e-320" + out); // omega = inf: 0 steps
    CHECK(tiny_mass.exit_code == 2);
    // The SPD protocols count their load steps, relaxation budgets and pulls from dt = dt_factor dt_c: a
    // dt_factor of 1e-310 made the count overflow an int (undefined), the walls jump to infinity and a contact
    // throw inside the OpenMP region (exit 134), or the budget turn negative (exit 3 "not reached in
    // -9223372036854775808 steps"). Each is refused before the run, naming dt_factor.
    for (const std::string scene :
         {"spd.ring_compression", "compare.ring", "spd.beam", "spd.compaction", "spd.tissue"}) {
        CAPTURE(scene);
        const Outcome tiny = run_softgrain("run " + scene + " --set dt_factor=1e-310" + out);
        CHECK(tiny.exit_code == 2);
        CHECK(contains(tiny.output, "'dt_factor' = 1e-310 makes"));
        CHECK(contains(tiny.output, "allowed: at most 1e+12 steps"));
    }
    // dpm.shear_friction's scan x_start..x_end in steps dx: x_start = 1e308 made its count 1e310, whose
    // reservation threw (exit 5, internal error); a reversed range ran an empty scan.
    const Outcome far_start = run_softgrain("run dpm.shear_friction --set x_start=1e308" + out);
    CHECK(far_start.exit_code == 2);
    CHECK(contains(far_start.output, "'x_end' = 0.7 is below 'x_start' = 1e+308"));
    const Outcome tiny_dx = run_softgrain("run dpm.shear_friction --set dx=1e-300" + out);
    CHECK(tiny_dx.exit_code == 2);
    CHECK(contains(tiny_dx.output, "steps; allowed: at most 2.14748e+09 steps"));
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("a run stopped by SIGTERM or SIGHUP removes its partial directory and its checkpoint lock; a later "
          "run removes stale partial directories")
{
    const fs::path dir = scratch_directory("signal");
    // periods = 1e6: 6e8 steps, far longer than the half second before the signal. (SIGINT takes the same
    // path, but a non-interactive shell starts background commands with SIGINT ignored.)
    for (const char* signal : {"TERM", "HUP"}) {
        CAPTURE(signal);
        const Outcome stopped = softgrain::verification::run_shell(
            std::string(SOFTGRAIN_EXECUTABLE) + " run core.harmonic --quiet --set periods=1000000 --out " +
            dir.string() + " & p=$!; sleep 0.5; kill -" + signal + " $p; wait $p; echo exit=$?");
        CHECK(
            contains(stopped.output, std::string("exit=") + (std::string(signal) == "TERM" ? "143" : "129")));
        CHECK(fs::is_empty(dir));
    }
    // A run that keeps checkpoints also leaves no lock file (nor a half-written checkpoint); the checkpoint
    // itself stays, for --resume.
    const Outcome checkpointing = softgrain::verification::run_shell(
        std::string(SOFTGRAIN_EXECUTABLE) + " run spd.compaction --quiet --checkpoint-every 0.1 --out " +
        dir.string() + " & p=$!; sleep 1.5; kill -TERM $p; wait $p; echo exit=$?");
    CHECK(contains(checkpointing.output, "exit=143"));
    for (const auto& entry : fs::directory_iterator(dir))
        CHECK(entry.path().filename() == "spd.compaction.checkpoint");
    fs::remove(dir / "spd.compaction.checkpoint");
    // With --vtk the frames of a checkpointing run wait beside the checkpoint for --resume; stopped before
    // its first checkpoint (every 600 s) it has none, so its frames go too.
    const Outcome framing = softgrain::verification::run_shell(
        std::string(SOFTGRAIN_EXECUTABLE) + " run spd.compaction --quiet --vtk --out " + dir.string() +
        " & p=$!; sleep 1.5; kill -TERM $p; wait $p; echo exit=$?");
    CHECK(contains(framing.output, "exit=143"));
    CHECK(fs::is_empty(dir));
    const Outcome framing_checkpointed = softgrain::verification::run_shell(
        std::string(SOFTGRAIN_EXECUTABLE) +
        " run spd.compaction --quiet --vtk --checkpoint-every 0.1 --out " + dir.string() +
        " & p=$!; sleep 1.5; kill -TERM $p; wait $p; echo exit=$?");
    CHECK(contains(framing_checkpointed.output, "exit=143"));
    CHECK(fs::exists(dir / "spd.compaction.checkpoint"));
    CHECK(fs::exists(dir / ".spd.compaction.vtk-frames"));
    fs::remove(dir / "spd.compaction.checkpoint");
    fs::remove_all(dir / ".spd.compaction.vtk-frames");
    // A partial directory whose process is gone (a SIGKILL): removed by the next run into the same place.
    fs::create_directories(dir / ".core.harmonic.partial-2147483000");
    REQUIRE(run_softgrain("run core.harmonic --quiet --out " + dir.string()).exit_code == 0);
    CHECK_FALSE(fs::exists(dir / ".core.harmonic.partial-2147483000"));
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
    fs::remove_all(dir);
}

TEST_CASE("a disk that fills up while a run writes its tables is an I/O failure (exit 4) that leaves nothing")
{
    const fs::path dir = scratch_directory("full");
    // A 64 KiB tmpfs: core.harmonic's trajectory (about 700 kB) cannot fit. Mounting needs root.
    if (std::system(("mount -t tmpfs -o size=64k tmpfs " + dir.string() + " 2>/dev/null").c_str()) != 0) {
        MESSAGE("skipped: mounting a tmpfs needs root");
        fs::remove_all(dir);
        return;
    }
    const Outcome run = run_softgrain("run core.harmonic --quiet --out " + dir.string());
    CHECK(run.exit_code == 4);
    CHECK(contains(run.output, "disk full"));
    CHECK(fs::is_empty(dir));
    CHECK(std::system(("umount " + dir.string()).c_str()) == 0);
    fs::remove_all(dir);
}

TEST_CASE("a force whose deflection the positions cannot resolve is refused, never run to exit 0 unmoved")
{
    const fs::path dir = scratch_directory("force");
    // force = 1e-30 once ran to exit 0 with every gap still at h0 and a force residual of 1.
    const Outcome tiny = run_softgrain("run sd.many --quiet --set force=1e-30 --out " + dir.string());
    CHECK(tiny.exit_code == 2);
    CHECK(contains(tiny.output, "'force' = 1e-30"));
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("a run never overwrites or deletes another run's checkpoint")
{
    const fs::path dir = scratch_directory("checkpoint");
    const std::string run = "run spd.compaction --quiet --set particles=4 --out " + dir.string();
    // An earlier run's checkpoint: a run without --resume is refused and leaves it as it was.
    write_file(dir / "spd.compaction.checkpoint", "an earlier run's state\n");
    const Outcome fresh = run_softgrain(run);
    CHECK(fresh.exit_code == 2);
    CHECK(contains(fresh.output, "--resume"));
    std::ifstream kept(dir / "spd.compaction.checkpoint");
    CHECK(std::string(std::istreambuf_iterator<char>(kept), {}) == "an earlier run's state\n");
    fs::remove(dir / "spd.compaction.checkpoint");
    // A run still going holds the checkpoint's lock (flock(1) stands in for it): refused, even with --resume.
    const Outcome concurrent =
        softgrain::verification::run_shell("flock " + (dir / "spd.compaction.checkpoint.lock").string() +
                                           " " + SOFTGRAIN_EXECUTABLE + " " + run + " --resume");
    CHECK(concurrent.exit_code == 2);
    CHECK(contains(concurrent.output, "another run that is still going"));
    fs::remove(dir / "spd.compaction.checkpoint.lock");
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("an absurd size is refused before anything is allocated, naming the parameters and the estimate")
{
    const fs::path dir = scratch_directory("absurd");
    for (const std::string scene : {"spd.compaction", "spd.bench", "dpm.jam"}) {
        CAPTURE(scene);
        const Outcome huge =
            run_softgrain("run " + scene + " --quiet --set particles=1000000000 --out " + dir.string());
        CHECK(huge.exit_code == 2);
        CHECK(contains(huge.output, "particles = 1000000000"));
        CHECK(contains(huge.output, "the run needs at least"));
    }
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("every size parameter of every scene is counted by the scene's memory estimate")
{
    // The integer parameters that set how much a scene allocates. At 2^31 - 1 each must make its scene's
    // estimate exceed 100 GB (four times the 24 GiB of the machines softgrain is tested on; a size left out
    // of an estimate would leave it at the default's few MB) for at least one choice of the scene's `model`
    // (a size a model ignores is not counted): such a run is refused at once instead of running out of
    // memory.
    const std::vector<std::string> sizes{"particles",     "nodes",          "nodes_small",  "nodes_large",
                                         "network_nodes", "boundary_nodes", "per_side",     "layers",
                                         "rows",          "columns",        "edge_segments"};
    const softgrain::SceneRegistry scenes = softgrain::all_scenes();
    for (const auto& scene : scenes.all())
        for (const auto& spec : scene.parameters) {
            if (spec.type != softgrain::ParameterType::integer ||
                std::find(sizes.begin(), sizes.end(), spec.name) == sizes.end() || spec.max < 1e6)
                continue;
            CAPTURE(scene.name);
            CAPTURE(spec.name);
            REQUIRE(scene.memory);
            std::vector<std::string> models{""};
            for (const auto& other : scene.parameters)
                if (other.name == "model") models = other.choices;
            double largest = 0;
            for (const auto& model : models) {
                softgrain::Parameters p(scene.parameters);
                if (!model.empty()) p.set_from_text("model", model);
                p.set_from_text(spec.name, "2147483647");
                largest = std::max(largest, scene.memory(p).bytes);
            }
            CHECK(largest > 1e11);
        }
}

TEST_CASE(
    "summary.json spells a computed non-finite value as \"nan\" or \"inf\", and \"not applicable\" as null")
{
    const fs::path dir = scratch_directory("spelling");
    softgrain::Parameters parameters({softgrain::ParameterSpec::real("x", 1.0, "1", "unused")});
    {
        softgrain::RunContext context(dir, "spelling", parameters, true);
        context.summary()["failed_fit"] = std::nan("");
        context.summary()["blow_up"] = -INFINITY;
        context.summary()["per_packing"] = {1.0, std::nan("")};
        context.summary()["no_flat_contact"] = softgrain::value_or_null(std::nullopt);
        context.commit();
    }
    const auto summary = nlohmann::json::parse(std::ifstream(dir / "spelling" / "summary.json"));
    CHECK(summary["failed_fit"] == "nan");
    CHECK(summary["blow_up"] == "-inf");
    CHECK(summary["per_packing"][1] == "nan");
    CHECK(summary["no_flat_contact"].is_null());
    fs::remove_all(dir);
}

TEST_CASE("a renamed parameter keeps its old name: dpm.jam's A0_floppy runs as A0 with identical results, "
          "describe marks it deprecated, and a refused value is named by the key typed")
{
    const Outcome describe = run_softgrain("describe dpm.jam");
    REQUIRE(describe.exit_code == 0);
    CHECK(contains(describe.output, "\nA0 "));
    CHECK(contains(describe.output, "deprecated name: A0_floppy"));

    // 12 floppy particles of 6 and 8 vertices (A_min(6) = 1.103) jammed at P_t = 1e-5, one target above.
    const std::string floppy =
        " --quiet --set model=floppy --set particles=12 --set nodes_small=6 --set "
        "nodes_large=8 --set pressure_onset=1e-5 --set pressures=1 --set pressure_max=2e-5";
    const fs::path dir = scratch_directory("renamed");
    const auto run = [&](const std::string& target, const std::string& settings, const std::string& name) {
        const fs::path out = dir / name;
        REQUIRE(run_softgrain("run " + target + floppy + settings + " --out " + out.string()).exit_code == 0);
        return out / (target.ends_with(".toml") ? fs::path(target).stem().string() : target);
    };
    // pressure.dat without its `# scene:` line (a scene file's run is named after the file).
    const auto table = [](const fs::path& run_dir) {
        std::ifstream file(run_dir / "pressure.dat");
        std::string text, line;
        while (std::getline(file, line))
            if (line.rfind("# scene:", 0) != 0) text += line + "\n";
        return text;
    };
    const auto summary = [](const fs::path& run_dir) {
        auto json = nlohmann::json::parse(std::ifstream(run_dir / "summary.json"));
        for (const char* measured : {"wall_time_s", "time_per_step_s", "peak_memory_mib", "scene"})
            json.erase(measured);
        return json;
    };
    const fs::path by_name = run("dpm.jam", " --set A0=1.12", "new");
    const fs::path by_old_name = run("dpm.jam", " --set A0_floppy=1.12", "old");
    write_file(dir / "floppy.toml", "scene = \"dpm.jam\"\nA0_floppy = 1.12\n");
    const fs::path by_file = run((dir / "floppy.toml").string(), "", "file");
    // The value is stored and reported under the new name, and every result is the same (deterministic).
    CHECK(summary(by_old_name)["parameters"]["A0"] == 1.12);
    CHECK(!summary(by_old_name)["parameters"].contains("A0_floppy"));
    CHECK(summary(by_old_name) == summary(by_name));
    CHECK(summary(by_file) == summary(by_name));
    CHECK(table(by_old_name) == table(by_name));
    CHECK(table(by_file) == table(by_name));
    // ... and it reaches the run: another A0 jams to another packing.
    const fs::path other = run("dpm.jam", " --set A0_floppy=1.2", "other");
    CHECK(summary(other)["phi_c"] != summary(by_name)["phi_c"]);

    // Out of the spec's range: the message names the key as typed (and the new name of an old one).
    const Outcome old_below = run_softgrain("run dpm.jam --set A0_floppy=0.9 --out " + dir.string());
    CHECK(old_below.exit_code == 2);
    CHECK(contains(old_below.output, "parameter 'A0_floppy' (now 'A0') = '0.9' is out of range"));
    const Outcome below = run_softgrain("run dpm.jam --set A0=0.9 --out " + dir.string());
    CHECK(below.exit_code == 2);
    CHECK(contains(below.output, "parameter 'A0' = '0.9' is out of range"));
    // Below A_min(6) of the small floppy particles: the protocol's one check of A0 against the polygons.
    const Outcome below_polygon =
        run_softgrain("run dpm.jam" + floppy + " --set A0=1.05 --out " + dir.string());
    CHECK(below_polygon.exit_code == 2);
    CHECK(contains(below_polygon.output, "A0 = 1.05"));
    CHECK(contains(below_polygon.output, "A_min(6)"));
    fs::remove_all(dir);
}
