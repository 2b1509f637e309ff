// `softgrain advise`: the cheapest run of a stored work-precision sweep within a tolerance, per method and
// overall; a sweep that cannot be read or a scene without one is bad input (exit 2) naming what is wrong.
#include "core/advice.hpp"
#include "core/errors.hpp"
#include "support/run_softgrain.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace softgrain;
using softgrain::verification::run_softgrain;

namespace {

// The layout of compare-ring-work-precision.dat as scripts/reproduce writes it (columns trimmed): SPD at two
// time steps, DPM; the errors fall as N^-2, the cost grows with N; one SPD run stopped with exit 3 (nan).
const char* const ring_sweep =
    R"(# generator: scripts/reproduce, figure compare-ring-work-precision, scale default
# scene: compare.ring; one row per run
method_index nodes dt_factor wall_time_s force_error_max
0.0 32.0 0.5 1.0 0.02
0.0 64.0 0.5 4.0 0.005
0.0 128.0 0.5 16.0 0.00125
0.0 32.0 0.7 0.8 0.02
0.0 64.0 0.7 3.0 nan
1.0 32.0 0.5 0.9 0.02
1.0 64.0 0.5 2.5 0.005
1.0 128.0 0.5 11.0 0.00125
)";

fs::path written(const std::string& name, const std::string& text)
{
    const fs::path path = fs::temp_directory_path() / (name + "-" + std::to_string(getpid()) + ".dat");
    std::ofstream(path) << text;
    return path;
}

SweepTable ring_table()
{
    return {"compare",         "compare-ring-work-precision",
            "method_index",    {"spd", "dpm"},
            "dt_factor",       "spd",
            "nodes",           "vertices N",
            "force_error_max", "max |F/F_el - 1|"};
}

} // namespace

TEST_CASE("advise picks, per method and overall, the cheapest run within the tolerance")
{
    const fs::path file = written("advice-ring", ring_sweep);
    const std::vector<SweepRun> runs = read_sweep(file, ring_table());
    REQUIRE(runs.size() == 8);
    CHECK(runs[3].method == "spd (dt_factor 0.7)");
    CHECK(runs[5].method == "dpm"); // DPM ignores dt_factor: no variant in its name
    CHECK(sweep_scale(file) == "default");

    const Advice advice = advise(runs, 0.006);
    REQUIRE(advice.methods.size() == 3);
    // SPD at 0.5 dt_c: N = 64 is the first within 0.006; DPM reaches it at the same N in less time.
    CHECK(advice.methods[0].met);
    CHECK(advice.methods[0].run.resolution == 64);
    // SPD at 0.7 dt_c: its N = 64 run stopped with a diagnosis (nan): nothing meets 0.006; the most accurate
    // finite run is reported instead.
    CHECK_FALSE(advice.methods[1].met);
    CHECK(advice.methods[1].run.resolution == 32);
    CHECK(advice.methods[2].met);
    REQUIRE(advice.recommended);
    CHECK(advice.recommended->method == "dpm");
    CHECK(advice.recommended->resolution == 64);
    CHECK(advice.recommended->cost_s == 2.5);

    // A tolerance no run meets: no recommendation, every method reports its most accurate run.
    const Advice none = advise(runs, 1e-4);
    CHECK_FALSE(none.recommended);
    CHECK(none.methods[0].run.resolution == 128);
    CHECK(none.methods[2].run.resolution == 128);
    fs::remove(file);
}

TEST_CASE(
    "a sweep table that is not the scene's, or is malformed, is bad input naming the file and the fault")
{
    const fs::path other = written("advice-other", "# generator: scripts/reproduce, figure x, scale smoke\n"
                                                   "nodes wall_time_s\n16.0 1.0\n");
    CHECK_THROWS_WITH_AS(read_sweep(other, ring_table()), doctest::Contains("has no column 'method_index'"),
                         InputError);
    const fs::path ragged =
        written("advice-ragged", "method_index nodes dt_factor wall_time_s force_error_max\n"
                                 "0.0 16.0 0.5 1.0\n");
    CHECK_THROWS_WITH_AS(read_sweep(ragged, ring_table()),
                         doctest::Contains("line 2: 4 values for 5 columns"), InputError);
    const fs::path code = written("advice-code", "method_index nodes dt_factor wall_time_s force_error_max\n"
                                                 "2.0 16.0 0.5 1.0 0.1\n");
    CHECK_THROWS_WITH_AS(read_sweep(code, ring_table()),
                         doctest::Contains("method_index = 2 is not a method code"), InputError);
    CHECK_THROWS_WITH_AS(locate_sweep(ring_table(), fs::path("/no/such/sweep.dat")),
                         doctest::Contains("--sweep = '/no/such/sweep.dat': no such file"), InputError);
    for (const fs::path& f : {other, ragged, code})
        fs::remove(f);
}

TEST_CASE(
    "softgrain advise answers from a stored sweep; bad input exits 2 naming the key and what is allowed")
{
    const fs::path file = written("advice-cli", ring_sweep);
    const auto answer = run_softgrain("advise compare.ring --tolerance 0.006 --sweep " + file.string());
    CHECK(answer.exit_code == 0);
    CHECK(answer.output.find(
              "recommended_method = dpm\nrecommended_resolution = 64\nrecommended_cost_s = 2.5") !=
          std::string::npos);

    const auto negative = run_softgrain("advise compare.ring --tolerance -1 --sweep " + file.string());
    CHECK(negative.exit_code == 2);
    CHECK(negative.output.find("--tolerance") != std::string::npos);

    const auto no_sweep = run_softgrain("advise core.harmonic --tolerance 0.01");
    CHECK(no_sweep.exit_code == 2);
    CHECK(no_sweep.output.find("has no stored work-precision sweep to advise from; allowed: ") !=
          std::string::npos);
    CHECK(no_sweep.output.find("compare.ring") != std::string::npos);
    CHECK(no_sweep.output.find("dpm.compress3d") != std::string::npos);

    const auto unknown = run_softgrain("advise no.such --tolerance 0.01");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output.find("unknown scene 'no.such'") != std::string::npos);
    fs::remove(file);
}
