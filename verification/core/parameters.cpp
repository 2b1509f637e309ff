// Typed scene parameters: parsing, ranges, infinity, choices; nothing is clamped.
#include "core/parameters.hpp"
#include "core/errors.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

using namespace softgrain;

namespace {

Parameters example()
{
    return Parameters({
        ParameterSpec::real("eta", 0.0, "1", "core-to-shell stiffness ratio")
            .non_negative()
            .infinity_allowed(),
        ParameterSpec::real("nu", 0.3, "1", "Poisson ratio").at_least(-1.0).below(0.5),
        ParameterSpec::integer("nodes", 64, "1", "vertices").at_least(3),
        ParameterSpec::boolean("unload", true, "unload after loading"),
        ParameterSpec::choice("support", "cantilever", {"cantilever", "simple"}, "beam support"),
        ParameterSpec::real("A0", 0.0, "1", "preferred shape parameter")
            .at_least(1.0)
            .keyword_by_default("min"),
    });
}

} // namespace

TEST_CASE("parameters parse by type and keep their defaults")
{
    Parameters p = example();
    CHECK(p.real("nu") == 0.3);
    p.set_from_text("eta", "inf");
    CHECK(std::isinf(p.real("eta")));
    p.set_from_text("nodes", "12");
    CHECK(p.integer("nodes") == 12);
    p.set_from_text("unload", "false");
    CHECK_FALSE(p.boolean("unload"));
    p.set_from_text("support", "simple");
    CHECK(p.choice("support") == "simple");
    CHECK(p.to_json()["eta"] == "inf");
}

TEST_CASE("out-of-range, malformed and unknown values are refused, never clamped")
{
    Parameters p = example();
    CHECK_THROWS_AS(p.set_from_text("nu", "0.5"), InputError);  // exclusive upper bound
    CHECK_THROWS_AS(p.set_from_text("nu", "0.3x"), InputError); // trailing garbage
    CHECK_THROWS_AS(p.set_from_text("nu", ""), InputError);     // empty
    CHECK_THROWS_AS(p.set_from_text("nu", "inf"), InputError);  // inf only where allowed
    CHECK_THROWS_AS(p.set_from_text("nodes", "2"), InputError); // below minimum
    CHECK_THROWS_AS(p.set_from_text("nodes", "12.5"), InputError);
    CHECK_THROWS_AS(p.set_from_text("unload", "yes"), InputError);
    CHECK_THROWS_AS(p.set_from_text("support", "fixed"), InputError);
    CHECK_THROWS_AS(p.set_from_text("colour", "red"), InputError);
    CHECK(p.real("nu") == 0.3); // the refused values changed nothing
    CHECK(p.integer("nodes") == 64);
    try {
        p.set_from_text("nu", "0.7");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) ==
              "parameter 'nu' = '0.7' is out of range; allowed: a real number >= -1 and < 0.5 [1]");
    }
}

TEST_CASE("TOML values: integers are accepted for reals, not the reverse; inf is a TOML literal")
{
    Parameters p = example();
    p.set_from_toml(toml::parse("eta = inf\nnu = 0\nnodes = 8\nsupport = 'simple'\n"), "test.toml");
    CHECK(std::isinf(p.real("eta")));
    CHECK(p.real("nu") == 0.0);
    CHECK(p.integer("nodes") == 8);
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("nodes = 8.0\n"), "test.toml"), InputError);
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("nu = inf\n"), "test.toml"), InputError);
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("unload = 1\n"), "test.toml"), InputError);
}

TEST_CASE("a keyword stands in for a computed real value; other words are still refused")
{
    Parameters p = example();
    CHECK(p.keyword("A0") == "min"); // the default
    CHECK_THROWS_AS((void)p.real("A0"), std::logic_error);
    p.set_from_text("A0", "1.2");
    CHECK_FALSE(p.keyword("A0"));
    CHECK(p.real("A0") == 1.2);
    CHECK_THROWS_AS(p.set_from_text("A0", "max"), InputError);
    CHECK_THROWS_AS(p.set_from_text("A0", "0.9"), InputError); // the range still holds for numbers
    CHECK(p.to_json()["A0"] == 1.2);
    p.set_from_toml(toml::parse("A0 = 'min'\n"), "test.toml");
    CHECK(p.keyword("A0") == "min");
    CHECK(p.to_json()["A0"] == "min");
    CHECK_FALSE(p.keyword("nu"));
    try {
        p.set_from_text("A0", "max");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) ==
              "parameter 'A0' = 'max' is not a real number; allowed: a real number >= 1, or min [1]");
    }
}

TEST_CASE("nan is refused from a TOML file as from --set: NaN passes no range check")
{
    Parameters p = example();
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("nu = nan\n"), "test.toml"), InputError);
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("eta = nan\n"), "test.toml"),
                    InputError); // inf allowed, nan not
    CHECK_THROWS_AS(p.set_from_text("nu", "nan"), InputError);
    CHECK(p.real("nu") == 0.3);
    CHECK(p.real("eta") == 0.0);
}

TEST_CASE("integers above INT_MAX are refused, not narrowed; seeds take the whole 63-bit range")
{
    Parameters p = example();
    CHECK_THROWS_AS(p.set_from_text("nodes", "4294967300"), InputError); // 2^32 + 4 would run as 4 in an int
    CHECK_THROWS_AS(p.set_from_text("nodes", "2147483648"), InputError); // INT_MAX + 1
    CHECK_THROWS_AS(p.set_from_toml(toml::parse("nodes = 1000000000000\n"), "test.toml"), InputError);
    p.set_from_text("nodes", "2147483647");
    CHECK(p.integer("nodes") == 2147483647);

    Parameters seeded({ParameterSpec::seed("seed", 1, "seed of the placement")});
    seeded.set_from_text("seed", "9223372036854775807");
    CHECK(seeded.integer("seed") == 9223372036854775807LL);
    CHECK_THROWS_AS(seeded.set_from_text("seed", "-1"), InputError);
}
