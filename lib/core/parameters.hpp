// Typed scene parameters: each has a name, a type, a default, a unit, an allowed range and a meaning.
//
// Values come from three places, in this order: the scene's defaults, a TOML scene file, and
// `--set key=value` on the command line. Every value is checked against its specification; an unknown
// key, a wrong type or a value out of range is an InputError naming the key, the value and what is allowed.
// Nothing is clamped.
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace toml {
inline namespace v3 {
class table;
}
} // namespace toml

namespace softgrain {

enum class ParameterType { real, integer, boolean, choice };

using ParameterValue = std::variant<double, long long, bool, std::string>;

// The specification of one parameter. Build with the named constructors and the chainable setters:
//   ParameterSpec::real("mass", 1.0, "kg", "mass of the oscillator").positive()
struct ParameterSpec
{
    std::string name;
    ParameterType type = ParameterType::real;
    ParameterValue default_value;
    std::string unit; // "1" for dimensionless quantities
    std::string description;
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_inclusive = true;
    bool max_inclusive = true;
    bool accepts_infinity = false;      // real parameters only: the literal "inf" is a meaningful value
    std::vector<std::string> keywords;  // real parameters only: words that stand for a computed value
    std::vector<std::string> choices;   // choice parameters only
    std::vector<std::string> old_names; // earlier names, still accepted (deprecated; `describe` says so)

    static ParameterSpec real(std::string name, double value, std::string unit, std::string description);
    static ParameterSpec integer(std::string name, long long value, std::string unit,
                                 std::string description);
    // A random seed: any integer from 0 to 2^63 - 1 (not bounded by INT_MAX as counts are).
    static ParameterSpec seed(std::string name, long long value, std::string description);
    static ParameterSpec boolean(std::string name, bool value, std::string description);
    static ParameterSpec choice(std::string name, std::string value, std::vector<std::string> choices,
                                std::string description);

    ParameterSpec& positive();             // value > 0
    ParameterSpec& non_negative();         // value >= 0
    ParameterSpec& at_least(double lower); // value >= lower
    ParameterSpec& below(double upper);    // value < upper
    ParameterSpec& at_most(double upper);  // value <= upper
    ParameterSpec& infinity_allowed();     // "inf" is accepted (e.g. eta = inf: incompressible core)
    // A word accepted in place of a number, whose value the scene computes (e.g. A0 = min: the shape
    // parameter of the regular polygon). keyword_by_default also makes it the default.
    ParameterSpec& keyword_allowed(std::string word);
    ParameterSpec& keyword_by_default(std::string word);
    // A renamed parameter keeps its old name as a deprecated alias: scene files and --set may still use
    // it, and the value is stored (and reported) under the new name.
    ParameterSpec& renamed_from(std::string old_name);

    std::string type_name() const;
    std::string allowed() const; // human-readable statement of what is allowed
};

std::string to_string(const ParameterValue& value);

// The values of one run, checked against the scene's specifications.
class Parameters
{
  public:
    explicit Parameters(std::vector<ParameterSpec> specs);

    // `--set key=value`: parses the text according to the parameter's type.
    void set_from_text(const std::string& key, const std::string& text);
    // Every key of a TOML table except `scene`; `origin` names the file in messages.
    void set_from_toml(const toml::table& table, const std::string& origin);

    double real(const std::string& name) const; // a logic error if the parameter holds a keyword
    // The keyword a real parameter holds, if it holds one instead of a number.
    std::optional<std::string> keyword(const std::string& name) const;
    long long integer(const std::string& name) const;
    bool boolean(const std::string& name) const;
    const std::string& choice(const std::string& name) const;

    const std::vector<ParameterSpec>& specs() const { return specs_; }
    nlohmann::json to_json() const;

  private:
    const ParameterSpec& spec(const std::string& name) const;
    // Checks `value` against `spec` and stores it; messages name `key`, the name the user typed.
    void assign(const ParameterSpec& spec, const std::string& key, ParameterValue value,
                const std::string& shown_value);
    const ParameterValue& value(const std::string& name, ParameterType expected) const;

    std::vector<ParameterSpec> specs_;
    std::map<std::string, ParameterValue> values_;
};

} // namespace softgrain
