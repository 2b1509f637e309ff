// ctest-label: slow
// Reliability of long runs (issue 4): spd.compaction and spd.tissue write checkpoints, and a run resumed from
// one ends bit for bit as the uninterrupted run, whether it was stopped while the deposit settles, during the
// loading or the unloading, or after tissue links broke; `softgrain run --resume` refuses a checkpoint of
// other parameters or scenes. Bit for bit is the only honest tolerance here: the resumed run executes the
// same floating-point operations in the same order (same binary, same thread count), so any difference is a
// missing piece of state.
#include "core/checkpoint.hpp"
#include "core/scene.hpp"
#include "spd/compaction.hpp"
#include "spd/tissue.hpp"
#include "support/run_softgrain.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

using namespace softgrain;
using namespace softgrain::spd;
namespace fs = std::filesystem;

namespace {

// The smoke scale of the compaction figures: 12 rings, about 3 s.
CompactionSetup small_setup()
{
    CompactionSetup setup = compaction_scene_defaults();
    setup.assembly.particles = 12;
    setup.strain_max = 0.15;
    setup.wall_speed = 3e-3;
    return setup;
}

fs::path scratch(const std::string& name)
{
    const fs::path dir =
        fs::temp_directory_path() / ("softgrain-resume-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

bool same_bits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Every recorded number of two results, compared bit for bit.
void check_identical(const CompactionResult& a, const CompactionResult& b)
{
    CHECK(a.steps == b.steps);
    CHECK(a.deposit.steps == b.deposit.steps);
    CHECK(same_bits(a.height0, b.height0));
    REQUIRE(a.states.size() == b.states.size());
    int differing = 0;
    for (std::size_t i = 0; i < a.states.size(); ++i) {
        const CompactionState &s = a.states[i], &t = b.states[i];
        for (auto [x, y] : {std::pair{s.strain, t.strain},
                            {s.force_top, t.force_top},
                            {s.force_bottom, t.force_bottom},
                            {s.solid_area, t.solid_area},
                            {s.kinetic_energy, t.kinetic_energy}})
            differing += !same_bits(x, y);
    }
    CHECK(differing == 0);
    REQUIRE(a.snapshots.size() == b.snapshots.size());
    for (std::size_t n = 0; n < a.snapshots.size(); ++n) {
        CHECK(a.snapshots[n].energy == b.snapshots[n].energy);
        CHECK(a.snapshots[n].particles == b.snapshots[n].particles);
    }
}

struct Interrupted
{
};

// Stops a run (throws Interrupted) at its first record after the writer saved a checkpoint within the part
// of the run where `inside` holds, so that the resumed run starts from a state inside that part.
class InterruptAfterNextSave
{
  public:
    explicit InterruptAfterNextSave(const Checkpoints& writer) : writer_(writer) {}
    void operator()(bool inside)
    {
        if (!inside) return;
        if (saved_on_entry_ < 0)
            saved_on_entry_ = writer_.saved();
        else if (writer_.saved() > saved_on_entry_)
            throw Interrupted{};
    }

  private:
    const Checkpoints& writer_;
    int saved_on_entry_ = -1;
};

Checkpoints checkpoints_at(const fs::path& file, double interval, bool resume)
{
    return Checkpoints(file, interval, resume, "spd.compaction", "{}", "test");
}

std::string read_file(const fs::path& path)
{
    std::ostringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("a compaction resumed from a checkpoint of its loading or unloading ends bit for bit as an "
          "uninterrupted one [issue 4]")
{
    const CompactionSetup setup = small_setup();
    const auto ignore_state = [](const Assembly&, const CompactionState&) {};
    const auto no_progress = [](double) {};
    const CompactionResult reference = compaction(setup, ignore_state, no_progress);
    const fs::path dir = scratch("library");
    for (const bool loading : {true, false}) {
        CAPTURE(loading);
        const fs::path file = dir / (loading ? "loading.checkpoint" : "unloading.checkpoint");
        // Interrupt at the first recorded state of the stage after a checkpoint was written in it: the run
        // then resumes from a state inside that stage.
        {
            Checkpoints writer = checkpoints_at(file, 0.02, false);
            InterruptAfterNextSave stop(writer);
            const auto interrupt = [&](const Assembly&, const CompactionState& st) {
                stop(st.loading == loading);
            };
            CHECK_THROWS_AS(compaction(setup, interrupt, no_progress, &writer), Interrupted);
        } // the interrupted run ends here, releasing its checkpoint
        REQUIRE(fs::exists(file));
        Checkpoints reader = checkpoints_at(file, 0, true);
        const CompactionResult resumed = compaction(setup, ignore_state, no_progress, &reader);
        CHECK(reader.resumed());
        check_identical(reference, resumed);
    }
    fs::remove_all(dir);
}

TEST_CASE("a tissue pull resumed from a checkpoint written after links broke ends bit for bit as an "
          "uninterrupted one [issue 4]")
{
    TissueSetup setup; // the smoke tissue of the figures: 5 x 5 cells, pulled to eps_h = 0.1, past its peak
    setup.columns = 5;
    setup.rows = 5;
    PullSetup pulling;
    pulling.strain_max = 0.1;
    Tissue whole = build_tissue(setup);
    const PullResult reference = pull(whole, pulling, [](double) {});
    REQUIRE(whole.model.broken_links() > 0);

    const fs::path dir = scratch("tissue");
    const fs::path file = dir / "spd.tissue.checkpoint";
    Tissue interrupted = build_tissue(setup);
    {
        Checkpoints writer(file, 0.05, false, "spd.tissue", "{}", "test");
        InterruptAfterNextSave stop(writer);
        const auto interrupt = [&](double) { stop(interrupted.model.broken_links() > 0); };
        CHECK_THROWS_AS(pull(interrupted, pulling, interrupt, &writer), Interrupted);
    } // the interrupted run ends here, releasing its checkpoint

    Tissue resumed_tissue = build_tissue(setup);
    Checkpoints reader(file, 0, true, "spd.tissue", "{}", "test");
    const PullResult resumed = pull(
        resumed_tissue, pulling, [](double) {}, &reader);
    CHECK(reader.resumed());
    CHECK(resumed.steps == reference.steps);
    CHECK(resumed_tissue.model.broken_links() == whole.model.broken_links());
    REQUIRE(resumed.records.size() == reference.records.size());
    int differing = 0;
    for (std::size_t i = 0; i < reference.records.size(); ++i) {
        const TissueRecord &a = reference.records[i], &b = resumed.records[i];
        differing += !same_bits(a.strain, b.strain) || !same_bits(a.force_top, b.force_top) ||
                     !same_bits(a.force_bottom, b.force_bottom) || a.broken != b.broken;
    }
    CHECK(differing == 0);
    REQUIRE(resumed.snapshots.size() == reference.snapshots.size());
    CHECK(resumed.snapshots.back().cells == reference.snapshots.back().cells);
    CHECK(resumed.snapshots.back().energy == reference.snapshots.back().energy);
    fs::remove_all(dir);
}

TEST_CASE(
    "softgrain run --resume after kill -9 writes the tables and results of the uninterrupted run [issue 4]")
{
    using verification::run_softgrain;
    const fs::path dir = scratch("cli");
    const std::string scene =
        "run spd.compaction --set particles=12 --set strain_max=0.15 --set wall_speed=3e-3 --quiet";
    const fs::path whole = dir / "whole", part = dir / "part";
    REQUIRE(run_softgrain(scene + " --out " + whole.string()).exit_code == 0);
    // The run is killed as soon as its first checkpoint is written (about 0.05 s into a run of ~3 s, while
    // the deposit settles), with a bounded wait.
    const fs::path checkpoint = part / "spd.compaction.checkpoint";
    const std::string kill_after_checkpoint =
        "sh -c '" + std::string(SOFTGRAIN_EXECUTABLE) + " " + scene + " --checkpoint-every 0.05 --out " +
        part.string() + " & pid=$!; n=0; while [ ! -f " + checkpoint.string() +
        " ] && [ $n -lt 400 ]; do sleep 0.025; n=$((n+1)); done; kill -9 $pid'";
    REQUIRE(std::system(kill_after_checkpoint.c_str()) == 0);
    REQUIRE(fs::exists(checkpoint));
    CHECK_FALSE(fs::exists(part / "spd.compaction")); // nothing that looks complete

    const auto resumed = run_softgrain(scene + " --resume --out " + part.string());
    REQUIRE(resumed.exit_code == 0);
    CHECK_FALSE(fs::exists(checkpoint)); // a complete run removes its checkpoint
    for (const std::string table : {"compaction.dat", "snapshot.dat"}) {
        CAPTURE(table);
        CHECK(read_file(whole / "spd.compaction" / table) == read_file(part / "spd.compaction" / table));
    }
    const auto a = nlohmann::json::parse(read_file(whole / "spd.compaction" / "summary.json"));
    const auto b = nlohmann::json::parse(read_file(part / "spd.compaction" / "summary.json"));
    CHECK(b["resumed_from_checkpoint"] == true);
    CHECK(a["resumed_from_checkpoint"] == false);
    for (const auto& [key, value] : a.items()) {
        // What the run cost and how it was run, not what it computed.
        if (key == "wall_time_s" || key == "time_per_step_s" || key == "peak_memory_mib" ||
            key == "checkpoints_written" || key == "resumed_from_checkpoint")
            continue;
        CAPTURE(key);
        CHECK(b[key] == value);
    }
    fs::remove_all(dir);
}

TEST_CASE("--resume refuses a checkpoint of other parameters, and scenes without checkpoints (exit 2)")
{
    using verification::run_softgrain;
    const fs::path dir = scratch("refuse");
    const fs::path file = dir / "spd.compaction.checkpoint";
    Parameters forty(all_scenes().find("spd.compaction").parameters);
    forty.set_from_text("particles", "40");
    Checkpoints(file, 1, false, "spd.compaction", forty.to_json().dump(), "test").save([](Archive&) {});
    const auto other =
        run_softgrain("run spd.compaction --set particles=12 --resume --quiet --out " + dir.string());
    CHECK(other.exit_code == 2);
    CAPTURE(other.output);
    CHECK(other.output.find("'particles' = 40 in the checkpoint, 12 here") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "spd.compaction"));

    const auto unsupported = run_softgrain("run core.harmonic --resume --quiet --out " + dir.string());
    CHECK(unsupported.exit_code == 2);
    CAPTURE(unsupported.output);
    CHECK(unsupported.output.find("allowed for: spd.compaction") != std::string::npos);
    fs::remove_all(dir);
}
