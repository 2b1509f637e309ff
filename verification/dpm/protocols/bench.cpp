// dpm.bench (issue 19): a tiny run of each dimension through the scene API. Its costs are measured, never
// asserted; what is checked is that its keys agree with each other and with the protocol they time: the
// rates are the counts over relax_seconds, each relaxation evaluates the forces once more than it iterates,
// the relaxations lie inside the protocol's time, the dense spectrum has one mode per degree of freedom (the
// lowest_modes ones of a tiling with replicate^dimension as many), and the FIRE iterations are those of the
// same protocol run directly (jam(), deterministic for a seed).
#include "core/errors.hpp"
#include "core/output.hpp"
#include "core/scene.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/scenes/scenes.hpp"
#include "support/tolerance.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace softgrain;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// The options of the dpm.jam protocol that a run of dpm.bench with parameters `p` times.
dpm::JamOptions jam_protocol_options(const Parameters& p)
{
    OptionBinding<dpm::JamOptions> binding;
    dpm::bind_jam_protocol(binding, [](dpm::JamOptions& options) -> dpm::JamOptions& { return options; });
    return binding.read(p);
}

// Runs dpm.bench with `settings` and returns its summary.json and parameters.
std::pair<nlohmann::json, Parameters>
run_bench(const std::vector<std::pair<std::string, std::string>>& settings)
{
    const SceneRegistry scenes = all_scenes();
    const Scene& scene = scenes.find("dpm.bench");
    Parameters p(scene.parameters);
    for (const auto& [key, value] : settings)
        p.set_from_text(key, value);
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("softgrain-dpm-bench-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    {
        RunContext context(dir, scene.name, p, true);
        scene.run(p, context);
        context.commit();
    }
    const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / scene.name / "summary.json"));
    std::filesystem::remove_all(dir);
    return {summary, p};
}

// The relations between the cost keys of a summary (any dimension) whose spectrum was dense, of the jammed
// packing itself, unless `lowest` modes of its tiling `replicate` times along each axis were asked for.
void check_cost_keys(const nlohmann::json& s, int dimension, long vertices, long lowest = 0,
                     long replicate = 1)
{
    const double evaluations = s["force_evaluations"].get<double>(),
                 seconds = s["fire_seconds"].get<double>();
    CHECK(s["dimension"].get<int>() == dimension);
    CHECK(s["vertices"].get<long>() == vertices);
    CHECK(s["degrees_of_freedom"].get<long>() == dimension * vertices);
    long copies = 1;
    for (int a = 0; a < dimension; ++a)
        copies *= replicate;
    CHECK(s["spectrum_degrees_of_freedom"].get<long>() == copies * dimension * vertices);
    CHECK(s["spectrum_modes"].get<long>() == (lowest > 0 ? lowest : copies * dimension * vertices));
    // Lanczos: at least one factorisation of M - sigma and one solve per mode; none for the dense spectrum.
    CHECK((s["spectrum_factorizations"].get<long>() >= 1) == (lowest > 0));
    CHECK(s["spectrum_solves"].get<long>() >= lowest);
    // One evaluation per iteration and one at the start of each relaxation (at least one relaxation).
    CHECK(s["fire_iterations"].get<long>() < s["force_evaluations"].get<long>());
    CHECK(s["steps"].get<long>() == s["fire_iterations"].get<long>());
    // The rates are the quotients they are said to be (a division: round-off).
    CHECK_CLOSE(s["force_evaluations_per_second"].get<double>(), evaluations / seconds,
                (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(s["vertex_force_evaluations_per_second"].get<double>(),
                static_cast<double>(vertices) * evaluations / seconds, (Tolerance{4 * round_off, 0}));
    // The relaxations are timed inside the protocol, the protocol and the spectrum inside the run.
    CHECK(seconds > 0);
    CHECK(seconds <= s["relax_seconds"].get<double>());
    CHECK(s["relax_seconds"].get<double>() <= s["jam_seconds"].get<double>());
    CHECK(s["jam_cpu_seconds"].get<double>() > 0);
    CHECK(s["spectrum_seconds"].get<double>() > 0);
    CHECK(s["jam_seconds"].get<double>() + s["spectrum_seconds"].get<double>() <=
          s["wall_time_s"].get<double>());
    CHECK(s["peak_memory_mib"].get<double>() > 0);
}

// The 2D case of both tests: 6 shells of 6/8 vertices jammed at P_t = 1e-5, one target above; plus `extra`.
std::vector<std::pair<std::string, std::string>>
six_shells(std::vector<std::pair<std::string, std::string>> extra = {})
{
    std::vector<std::pair<std::string, std::string>> settings{
        {"model", "shell"},         {"particles", "6"}, {"nodes_small", "6"},    {"nodes_large", "8"},
        {"pressure_onset", "1e-5"}, {"pressures", "1"}, {"pressure_max", "2e-5"}};
    settings.insert(settings.end(), extra.begin(), extra.end());
    return settings;
}

// The 3D case: 4 shell icosahedra jammed at P_t = 1e-5 k_v v0, one target above; plus `extra`.
std::vector<std::pair<std::string, std::string>>
four_icosahedra(std::vector<std::pair<std::string, std::string>> extra = {})
{
    std::vector<std::pair<std::string, std::string>> settings{
        {"dimension", "3"},    {"model", "shell"},         {"particles", "4"}, {"nodes_small", "12"},
        {"nodes_large", "12"}, {"pressure_onset", "1e-5"}, {"pressures", "1"}, {"pressure_max", "2e-5"}};
    settings.insert(settings.end(), extra.begin(), extra.end());
    return settings;
}

} // namespace

TEST_CASE("dpm.bench in 2D: consistent cost keys, and the FIRE iterations of dpm.jam's protocol [issue 19]")
{
    const auto [summary, p] = run_bench(six_shells());
    check_cost_keys(summary, 2, 6 * (6 + 8) / 2);
    const dpm::JamResult direct = dpm::jam(jam_protocol_options(p));
    CHECK(summary["fire_iterations"].get<long>() == direct.fire_iterations);
    CHECK(summary["force_evaluations"].get<long>() == direct.force_evaluations);
    // FIRE alone (the default relaxation): no Newton finisher.
    CHECK(summary["newton_handovers"].get<long>() == 0);
    CHECK(summary["newton_steps"].get<long>() == 0);
    CHECK(summary["newton_factorizations"].get<long>() == 0);
}

TEST_CASE("dpm.bench in 2D with relaxation = fire_newton: the finisher's counts are those of dpm.jam's "
          "protocol [issue 19]")
{
    const auto [summary, p] = run_bench(six_shells({{"relaxation", "fire_newton"}}));
    check_cost_keys(summary, 2, 6 * (6 + 8) / 2);
    const dpm::JamResult direct = dpm::jam(jam_protocol_options(p));
    CHECK(summary["fire_iterations"].get<long>() == direct.fire_iterations);
    CHECK(summary["newton_handovers"].get<long>() == direct.handovers);
    CHECK(summary["newton_steps"].get<long>() == direct.newton_steps);
    CHECK(summary["newton_factorizations"].get<long>() == direct.factorizations);
    // Every hand-over takes at least one factorisation, every accepted step one.
    CHECK(direct.handovers > 0);
    CHECK(direct.factorizations >= direct.newton_steps);
    CHECK(direct.factorizations >= direct.handovers);
}

TEST_CASE("dpm.bench in 3D: consistent cost keys on the 3D protocol [issue 19]")
{
    const auto [summary, p] = run_bench(four_icosahedra());
    check_cost_keys(summary, 3, 4 * 12);
}

TEST_CASE("dpm.bench in 3D: the lowest modes of the jammed packing tiled 2 x 2 x 2 [issue 19]")
{
    const auto [summary, p] = run_bench(four_icosahedra({{"replicate", "2"}, {"lowest_modes", "20"}}));
    check_cost_keys(summary, 3, 4 * 12, 20, 2);
}

TEST_CASE("dpm.bench refuses more lowest modes than the spectrum has degrees of freedom [issue 19]")
{
    // 6 shells of 6/8 vertices: 84 degrees of freedom, 336 tiled 2 x 2.
    CHECK_THROWS_AS(run_bench(six_shells({{"lowest_modes", "84"}})), InputError);
    CHECK_THROWS_AS(run_bench(six_shells({{"lowest_modes", "336"}, {"replicate", "2"}})), InputError);
    CHECK_THROWS_AS(run_bench(six_shells({{"replicate", "0"}})), InputError);
}

TEST_CASE("dpm.bench in 3D refuses disks and vertex counts that name no mesh [issue 19]")
{
    CHECK_THROWS_AS(run_bench({{"dimension", "3"}, {"model", "smooth_disk"}}), InputError);
    CHECK_THROWS_AS(
        run_bench({{"dimension", "3"}, {"model", "shell"}, {"nodes_small", "12"}, {"nodes_large", "42"}}),
        InputError);
}
