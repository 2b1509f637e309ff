#include "core/parameters.hpp"

#include "core/errors.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

namespace softgrain {

namespace {

std::string format_number(double x)
{
    return number_text(x, 12);
}

std::string join(const std::vector<std::string>& words, const std::string& separator)
{
    std::string joined;
    for (const auto& word : words)
        joined += (joined.empty() ? "" : separator) + word;
    return joined;
}

// Refuses the value the user gave as `key`: the parameter's name, or an old name of it (named with the new).
[[noreturn]] void refuse(const ParameterSpec& spec, const std::string& key, const std::string& shown_value,
                         const std::string& why)
{
    const std::string named = key == spec.name ? "'" + key + "'" : "'" + key + "' (now '" + spec.name + "')";
    throw InputError("parameter " + named + " = '" + shown_value + "' " + why +
                     "; allowed: " + spec.allowed());
}

// Whole-string parse: "1.5x" or "" are refused, not read as 1.5 or 0.
std::optional<double> parse_real(const std::string& text, bool accepts_infinity)
{
    if (text == "inf" || text == "+inf" || text == "infinity")
        return accepts_infinity ? std::optional<double>(std::numeric_limits<double>::infinity())
                                : std::nullopt;
    double value = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

bool is_keyword(const ParameterSpec& spec, const std::string& text)
{
    for (const auto& word : spec.keywords)
        if (word == text) return true;
    return false;
}

std::optional<long long> parse_integer(const std::string& text)
{
    long long value = 0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

} // namespace

namespace {

ParameterSpec make_spec(std::string name, ParameterType type, ParameterValue value, std::string unit,
                        std::string description)
{
    ParameterSpec spec;
    spec.name = std::move(name);
    spec.type = type;
    spec.default_value = std::move(value);
    spec.unit = std::move(unit);
    spec.description = std::move(description);
    return spec;
}

} // namespace

ParameterSpec ParameterSpec::real(std::string name, double value, std::string unit, std::string description)
{
    return make_spec(std::move(name), ParameterType::real, value, std::move(unit), std::move(description));
}

ParameterSpec ParameterSpec::integer(std::string name, long long value, std::string unit,
                                     std::string description)
{
    // Scenes count in int: every integer parameter is refused above INT_MAX rather than narrowed (4294967300
    // particles would otherwise run as 4). A scene may bound it lower with at_most().
    ParameterSpec spec =
        make_spec(std::move(name), ParameterType::integer, value, std::move(unit), std::move(description));
    return spec.at_most(std::numeric_limits<int>::max());
}

ParameterSpec ParameterSpec::seed(std::string name, long long value, std::string description)
{
    ParameterSpec spec =
        make_spec(std::move(name), ParameterType::integer, value, "1", std::move(description)).non_negative();
    return spec.at_most(static_cast<double>(std::numeric_limits<long long>::max()));
}

ParameterSpec ParameterSpec::boolean(std::string name, bool value, std::string description)
{
    return make_spec(std::move(name), ParameterType::boolean, value, std::string(1, '-'),
                     std::move(description));
}

ParameterSpec ParameterSpec::choice(std::string name, std::string value, std::vector<std::string> choices,
                                    std::string description)
{
    ParameterSpec spec = make_spec(std::move(name), ParameterType::choice, std::move(value),
                                   std::string(1, '-'), std::move(description));
    spec.choices = std::move(choices);
    return spec;
}

ParameterSpec& ParameterSpec::positive()
{
    min = 0.0;
    min_inclusive = false;
    return *this;
}

ParameterSpec& ParameterSpec::non_negative()
{
    return at_least(0.0);
}

ParameterSpec& ParameterSpec::at_least(double lower)
{
    min = lower;
    min_inclusive = true;
    return *this;
}

ParameterSpec& ParameterSpec::below(double upper)
{
    max = upper;
    max_inclusive = false;
    return *this;
}

ParameterSpec& ParameterSpec::at_most(double upper)
{
    max = upper;
    max_inclusive = true;
    return *this;
}

ParameterSpec& ParameterSpec::infinity_allowed()
{
    accepts_infinity = true;
    return *this;
}

ParameterSpec& ParameterSpec::keyword_allowed(std::string word)
{
    keywords.push_back(std::move(word));
    return *this;
}

ParameterSpec& ParameterSpec::keyword_by_default(std::string word)
{
    default_value = word;
    return keyword_allowed(std::move(word));
}

ParameterSpec& ParameterSpec::renamed_from(std::string old_name)
{
    old_names.push_back(std::move(old_name));
    return *this;
}

std::string ParameterSpec::type_name() const
{
    switch (type) {
    case ParameterType::real:
        return "real";
    case ParameterType::integer:
        return "integer";
    case ParameterType::boolean:
        return "boolean";
    case ParameterType::choice:
        return "choice";
    }
    return "?";
}

std::string ParameterSpec::allowed() const
{
    if (type == ParameterType::boolean) return "true or false";
    std::ostringstream statement;
    if (type == ParameterType::choice) {
        statement << "one of " << join(choices, " | ");
        return statement.str();
    }
    statement << (type == ParameterType::integer ? "an integer" : "a real number");
    if (std::isfinite(min)) statement << (min_inclusive ? " >= " : " > ") << format_number(min);
    if (std::isfinite(min) && std::isfinite(max)) statement << " and";
    if (std::isfinite(max)) statement << (max_inclusive ? " <= " : " < ") << format_number(max);
    if (accepts_infinity) statement << ", or inf";
    for (const auto& word : keywords)
        statement << ", or " << word;
    if (unit != "-" && !unit.empty()) statement << " [" << unit << "]";
    return statement.str();
}

std::string to_string(const ParameterValue& value)
{
    struct Printer
    {
        std::string operator()(double x) const { return format_number(x); }
        std::string operator()(long long n) const { return std::to_string(n); }
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(const std::string& s) const { return s; }
    };
    return std::visit(Printer{}, value);
}

Parameters::Parameters(std::vector<ParameterSpec> specs) : specs_(std::move(specs))
{
    for (const auto& spec : specs_)
        values_[spec.name] = spec.default_value;
}

const ParameterSpec& Parameters::spec(const std::string& name) const
{
    for (const auto& candidate : specs_)
        if (candidate.name == name) return candidate;
    for (const auto& candidate : specs_)
        for (const auto& old_name : candidate.old_names)
            if (old_name == name) return candidate;
    std::vector<std::string> names;
    for (const auto& candidate : specs_)
        names.push_back(candidate.name);
    throw InputError("unknown parameter '" + name + "'; allowed: " + join(names, ", "));
}

void Parameters::assign(const ParameterSpec& spec, const std::string& key, ParameterValue value,
                        const std::string& shown_value)
{
    if (spec.type == ParameterType::choice) {
        const auto& word = std::get<std::string>(value);
        bool known = false;
        for (const auto& allowed : spec.choices)
            known = known || allowed == word;
        if (!known) refuse(spec, key, shown_value, "is not a known choice");
    } else if (spec.type == ParameterType::real && std::holds_alternative<std::string>(value)) {
        if (!is_keyword(spec, std::get<std::string>(value)))
            refuse(spec, key, shown_value, "is not a real number");
    } else if (spec.type != ParameterType::boolean) {
        const double x = spec.type == ParameterType::real ? std::get<double>(value)
                                                          : static_cast<double>(std::get<long long>(value));
        if (std::isnan(x))
            refuse(spec, key, shown_value, "is not a number"); // e.g. `dt = nan` in a TOML file
        const bool infinite_ok = std::isinf(x) && x > 0 && spec.accepts_infinity;
        const bool below_min = spec.min_inclusive ? x < spec.min : x <= spec.min;
        const bool above_max = spec.max_inclusive ? x > spec.max : x >= spec.max;
        if (!infinite_ok && (below_min || above_max)) refuse(spec, key, shown_value, "is out of range");
    }
    values_[spec.name] = std::move(value);
}

void Parameters::set_from_text(const std::string& key, const std::string& text)
{
    const ParameterSpec& s = spec(key);
    switch (s.type) {
    case ParameterType::real: {
        if (is_keyword(s, text)) {
            assign(s, key, text, text);
            return;
        }
        auto x = parse_real(text, s.accepts_infinity);
        if (!x) refuse(s, key, text, "is not a real number");
        assign(s, key, *x, text);
        return;
    }
    case ParameterType::integer: {
        auto n = parse_integer(text);
        if (!n) refuse(s, key, text, "is not an integer");
        assign(s, key, *n, text);
        return;
    }
    case ParameterType::boolean:
        if (text != "true" && text != "false") refuse(s, key, text, "is not a boolean");
        assign(s, key, text == "true", text);
        return;
    case ParameterType::choice:
        assign(s, key, text, text);
        return;
    }
}

void Parameters::set_from_toml(const toml::table& table, const std::string& origin)
{
    for (const auto& [key_view, node] : table) {
        const std::string key(key_view.str());
        if (key == "scene") continue;
        const ParameterSpec* s = nullptr;
        try {
            s = &spec(key);
        } catch (const InputError& e) {
            throw InputError(origin + ": " + e.what());
        }
        std::ostringstream shown;
        node.visit([&](const auto& concrete) { shown << concrete; });
        const auto wrong_type = [&] {
            std::ostringstream toml_type;
            toml_type << node.type();
            throw InputError(origin + ": parameter '" + key + "' = '" + shown.str() +
                             "' has the wrong type (a TOML " + toml_type.str() +
                             "); allowed: " + s->allowed());
        };
        try {
            switch (s->type) {
            case ParameterType::real: {
                if (node.is_string() && is_keyword(*s, *node.value<std::string>())) {
                    assign(*s, key, *node.value<std::string>(), shown.str());
                    break;
                }
                std::optional<double> x;
                if (node.is_floating_point() || node.is_integer())
                    x = node.value<double>();
                else if (node.is_string())
                    x = parse_real(*node.value<std::string>(), s->accepts_infinity);
                if (!x) wrong_type();
                if (std::isinf(*x) && !s->accepts_infinity) refuse(*s, key, shown.str(), "is not finite");
                assign(*s, key, *x, shown.str());
                break;
            }
            case ParameterType::integer:
                if (!node.is_integer()) wrong_type();
                assign(*s, key, *node.value<long long>(), shown.str());
                break;
            case ParameterType::boolean:
                if (!node.is_boolean()) wrong_type();
                assign(*s, key, *node.value<bool>(), shown.str());
                break;
            case ParameterType::choice:
                if (!node.is_string()) wrong_type();
                assign(*s, key, *node.value<std::string>(), shown.str());
                break;
            }
        } catch (const InputError& e) {
            const std::string message = e.what();
            if (message.rfind(origin, 0) == 0) throw;
            throw InputError(origin + ": " + message);
        }
    }
}

const ParameterValue& Parameters::value(const std::string& name, ParameterType expected) const
{
    const ParameterSpec& s = spec(name);
    if (s.type != expected)
        throw std::logic_error("parameter '" + name + "' is a " + s.type_name() + ", read as another type");
    return values_.at(name);
}

double Parameters::real(const std::string& name) const
{
    const ParameterValue& v = value(name, ParameterType::real);
    if (const auto* word = std::get_if<std::string>(&v))
        throw std::logic_error("parameter '" + name + "' holds the keyword '" + *word +
                               "'; ask Parameters::keyword first");
    return std::get<double>(v);
}

std::optional<std::string> Parameters::keyword(const std::string& name) const
{
    const ParameterValue& v = value(name, ParameterType::real);
    if (const auto* word = std::get_if<std::string>(&v)) return *word;
    return std::nullopt;
}

long long Parameters::integer(const std::string& name) const
{
    return std::get<long long>(value(name, ParameterType::integer));
}

bool Parameters::boolean(const std::string& name) const
{
    return std::get<bool>(value(name, ParameterType::boolean));
}

const std::string& Parameters::choice(const std::string& name) const
{
    return std::get<std::string>(value(name, ParameterType::choice));
}

nlohmann::json Parameters::to_json() const
{
    nlohmann::json json = nlohmann::json::object();
    for (const auto& s : specs_) {
        const auto& v = values_.at(s.name);
        if (s.type == ParameterType::real && std::holds_alternative<double>(v) &&
            std::isinf(std::get<double>(v)))
            json[s.name] = "inf";
        else
            std::visit([&](const auto& x) { json[s.name] = x; }, v);
    }
    return json;
}

} // namespace softgrain
