// Scene parameters declared once and bound to an options struct (core/option_binding.hpp): the specs take
// their defaults from the struct, a run fills every field from the values given, integers are checked as
// ints, choices become enums, cross-parameter checks name the keys, and a renamed key stays accepted.
#include "core/option_binding.hpp"
#include "core/errors.hpp"

#include <doctest/doctest.h>

#include <optional>
#include <string>

using namespace softgrain;

namespace {

enum class Support { cantilever, simple };

struct BeamOptions
{
    double length = 2.5;
    int nodes = 64;
    long steps = 100000;
    std::uint64_t seed = 7;
    bool unload = true;
    Support support = Support::simple;
    double strain_step = 0.01;
    double strain_max = 0.5;
};

OptionBinding<BeamOptions> beam_binding()
{
    OptionBinding<BeamOptions> b;
    b.real(&BeamOptions::length, "length", "m", "beam length").positive();
    b.integer(&BeamOptions::nodes, "nodes", "1", "vertices").at_least(3).renamed_from("vertices");
    b.count(&BeamOptions::steps, "steps", "1", "time steps").at_least(1);
    b.seed(&BeamOptions::seed, "seed", "random seed");
    b.boolean(&BeamOptions::unload, "unload", "unload after loading");
    b.choice(&BeamOptions::support, "support",
             {{"cantilever", Support::cantilever}, {"simple", Support::simple}}, "beam support");
    b.real(&BeamOptions::strain_step, "strain_step", "1", "strain increment").positive();
    b.real(&BeamOptions::strain_max, "strain_max", "1", "largest strain").positive();
    b.check([](const BeamOptions& o) {
        if (o.strain_step > o.strain_max)
            throw InputError("'strain_step' = " + std::to_string(o.strain_step) + " exceeds 'strain_max' = " +
                             std::to_string(o.strain_max) + "; allowed: strain_step <= strain_max");
    });
    return b;
}

const ParameterSpec& spec_named(const std::vector<ParameterSpec>& specs, const std::string& name)
{
    for (const ParameterSpec& spec : specs)
        if (spec.name == name) return spec;
    FAIL("no parameter " << name);
    throw std::logic_error("unreachable");
}

} // namespace

TEST_CASE("the specs take their defaults from the options struct, declared once")
{
    const OptionBinding<BeamOptions> binding = beam_binding();
    const std::vector<ParameterSpec>& specs = binding.specs();
    REQUIRE(specs.size() == 8);
    CHECK(std::get<double>(spec_named(specs, "length").default_value) == 2.5);
    CHECK(std::get<long long>(spec_named(specs, "nodes").default_value) == 64);
    CHECK(std::get<long long>(spec_named(specs, "steps").default_value) == 100000);
    CHECK(std::get<long long>(spec_named(specs, "seed").default_value) == 7);
    CHECK(std::get<bool>(spec_named(specs, "unload").default_value) == true);
    CHECK(std::get<std::string>(spec_named(specs, "support").default_value) == "simple");
    CHECK(spec_named(specs, "length").unit == "m");
    // Nothing given: the run's options are the struct's defaults, field by field.
    const BeamOptions options = binding.read(Parameters(specs));
    CHECK(options.length == 2.5);
    CHECK(options.nodes == 64);
    CHECK(options.steps == 100000);
    CHECK(options.seed == 7);
    CHECK(options.unload);
    CHECK(options.support == Support::simple);
}

TEST_CASE("given values fill their fields; choices become enums")
{
    const OptionBinding<BeamOptions> binding = beam_binding();
    Parameters p(binding.specs());
    p.set_from_text("length", "0.75");
    p.set_from_text("nodes", "12");
    p.set_from_text("steps", "3000000000"); // above INT_MAX: a long count holds it
    p.set_from_text("seed", "9223372036854775807");
    p.set_from_text("unload", "false");
    p.set_from_text("support", "cantilever");
    const BeamOptions options = binding.read(p);
    CHECK(options.length == 0.75);
    CHECK(options.nodes == 12);
    CHECK(options.steps == 3000000000L);
    CHECK(options.seed == 9223372036854775807ULL);
    CHECK_FALSE(options.unload);
    CHECK(options.support == Support::cantilever);
}

TEST_CASE("integers are checked as ints, not narrowed; ranges and choices are the specs'")
{
    const OptionBinding<BeamOptions> binding = beam_binding();
    Parameters p(binding.specs());
    // 2^32 + 4 would run as 4 vertices if narrowed.
    CHECK_THROWS_WITH_AS(p.set_from_text("nodes", "4294967300"), doctest::Contains("'nodes'"), InputError);
    CHECK_THROWS_WITH_AS(p.set_from_text("nodes", "2"), doctest::Contains(">= 3"), InputError);
    CHECK_THROWS_WITH_AS(p.set_from_text("support", "clamped"), doctest::Contains("cantilever | simple"),
                         InputError);
}

TEST_CASE("cross-parameter checks run before the scene, naming the keys a user typed")
{
    const OptionBinding<BeamOptions> binding = beam_binding();
    Parameters p(binding.specs());
    p.set_from_text("strain_step", "0.6");
    CHECK_THROWS_WITH_AS(binding.read(p), doctest::Contains("'strain_step' = 0.6"), InputError);
    p.set_from_text("strain_max", "0.6");
    CHECK(binding.read(p).strain_step == 0.6);
}

TEST_CASE("a renamed parameter keeps its old name as an alias, stored under the new one")
{
    const OptionBinding<BeamOptions> binding = beam_binding();
    Parameters p(binding.specs());
    p.set_from_text("vertices", "20");
    CHECK(binding.read(p).nodes == 20);
    CHECK(p.integer("nodes") == 20);
    CHECK(spec_named(binding.specs(), "nodes").old_names == std::vector<std::string>{"vertices"});
    CHECK_THROWS_WITH_AS(p.set_from_text("vertexes", "20"), doctest::Contains("unknown parameter 'vertexes'"),
                         InputError);
}

TEST_CASE("a parameter declared twice is a defect of the scene, found at registration")
{
    OptionBinding<BeamOptions> binding;
    binding.real(&BeamOptions::length, "length", "m", "beam length");
    CHECK_THROWS_AS(binding.real(&BeamOptions::strain_max, "length", "1", "again"), std::logic_error);
}

TEST_CASE("a library setup takes the scene's own defaults; nested fields bind through accessors")
{
    struct Ring
    {
        double eta = 0;
    };
    struct Setup
    {
        Ring ring;
        int particles = 100; // the library's default, not the scene's
    };
    Setup scene_defaults;
    scene_defaults.particles = 40;
    scene_defaults.ring.eta = 2.0;
    OptionBinding<Setup> binding(scene_defaults);
    binding.integer(&Setup::particles, "particles", "1", "rings");
    binding.real([](Setup& setup) -> double& { return setup.ring.eta; }, "eta", "1", "core stiffness ratio");
    CHECK(std::get<long long>(spec_named(binding.specs(), "particles").default_value) == 40);
    CHECK(std::get<double>(spec_named(binding.specs(), "eta").default_value) == 2.0);
    Parameters p(binding.specs());
    p.set_from_text("eta", "3.5");
    const Setup setup = binding.read(p);
    CHECK(setup.ring.eta == 3.5);
    CHECK(setup.particles == 40);
}

TEST_CASE("a real a keyword stands for: the number, or nothing for the keyword")
{
    struct Shape
    {
        std::optional<double> A0;        // nothing: the keyword `min` by default
        std::optional<double> A1 = 1.04; // a number by default, `min` allowed
    };
    OptionBinding<Shape> binding;
    binding.real_or_keyword(&Shape::A0, "A0", "min", "1", "preferred shape").at_least(1.0);
    binding.real_or_keyword(&Shape::A1, "A1", "min", "1", "preferred shape").at_least(1.0);
    CHECK(std::get<std::string>(spec_named(binding.specs(), "A0").default_value) == "min");
    CHECK(std::get<double>(spec_named(binding.specs(), "A1").default_value) == 1.04);
    Parameters p(binding.specs());
    const Shape defaults = binding.read(p);
    CHECK_FALSE(defaults.A0.has_value());
    CHECK(defaults.A1 == 1.04);
    p.set_from_text("A0", "1.2");
    p.set_from_text("A1", "min");
    const Shape given = binding.read(p);
    CHECK(given.A0 == 1.2);
    CHECK_FALSE(given.A1.has_value());
    CHECK_THROWS_WITH_AS(p.set_from_text("A0", "max"), doctest::Contains("'A0'"), InputError);
    CHECK_THROWS_WITH_AS(p.set_from_text("A0", "0.9"), doctest::Contains(">= 1"), InputError);
}
