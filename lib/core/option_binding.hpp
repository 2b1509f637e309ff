// Scene parameters declared once, bound to the field of the options struct they fill.
//
// A scene's options are a struct whose values in one object are the defaults: the struct's member
// initialisers, or a library setup with the scene's own defaults set on it (OptionBinding(defaults)). The
// binding names each field once, with its unit, meaning and allowed range; a field is a data member
// pointer or, for a nested field, a function returning a reference to it
// ([](Setup& s) -> double& { return s.ring.eta; }). From that one declaration it makes the ParameterSpecs
// that `describe` prints and the run checks (the defaults are read from the defaults object, never
// repeated), and it fills and checks the struct for a run:
//
//   struct HarmonicOptions { double mass = 1.0; double dt = 1e-3; };
//   OptionBinding<HarmonicOptions> harmonic_binding()
//   {
//       OptionBinding<HarmonicOptions> b;
//       b.real(&HarmonicOptions::mass, "mass", "kg", "mass m").positive();
//       b.real(&HarmonicOptions::dt, "dt", "s", "time step").positive();
//       b.check([](const HarmonicOptions& o) { ... throw InputError naming the keys ... });
//       return b;
//   }
//   registry.add(bound_scene("core.harmonic", "...", harmonic_binding(), run_harmonic));
//
// Integers are range-checked as ints by their spec (never narrowed), choices become enums here (no string
// comparison inside the library), and the cross-parameter checks run after every field is filled and
// before any work starts, with messages that name the keys a user types.
#pragma once

#include "core/parameters.hpp"
#include "core/resources.hpp"
#include "core/scene.hpp"

#include <concepts>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace softgrain {

// A field of Options holding a Value: a data member pointer, or a function of Options& returning Value&.
template <class F, class Options, class Value>
concept Field = requires(F field, Options& options)
{
    {
        std::invoke(field, options)
        } -> std::same_as<Value&>;
};

// A nested field as one: path(&Setup::ring, &RingSetup::material, &ShellMaterial::h) is a Field of Setup.
template <class First, class... Rest>
auto path(First first, Rest... rest)
{
    return [=](auto& object) -> decltype(auto) {
        if constexpr (sizeof...(Rest) == 0)
            return std::invoke(first, object);
        else
            return path(rest...)(std::invoke(first, object));
    };
}

template <class Options>
class OptionBinding
{
  public:
    using Check = std::function<void(const Options&)>;

    // The type a field holds (the enum of a choice).
    template <class F>
    using FieldValue = std::remove_reference_t<std::invoke_result_t<F, Options&>>;

    explicit OptionBinding(Options defaults = Options{}) : defaults_(std::move(defaults)) {}

    template <Field<Options, double> F>
    ParameterSpec& real(F field, std::string name, std::string unit, std::string meaning)
    {
        return bind(
            field,
            ParameterSpec::real(std::move(name), default_of(field), std::move(unit), std::move(meaning)),
            [](const Parameters& p, const std::string& key) { return p.real(key); });
    }

    // An int field: its spec refuses values above INT_MAX (ParameterSpec::integer), so the cast cannot narrow.
    template <Field<Options, int> F>
    ParameterSpec& integer(F field, std::string name, std::string unit, std::string meaning)
    {
        return bind(
            field,
            ParameterSpec::integer(std::move(name), default_of(field), std::move(unit), std::move(meaning)),
            [](const Parameters& p, const std::string& key) { return static_cast<int>(p.integer(key)); });
    }

    // A long field (step counts): the whole range of a long, which is that of the parsed long long here.
    template <Field<Options, long> F>
    ParameterSpec& count(F field, std::string name, std::string unit, std::string meaning)
    {
        static_assert(sizeof(long) == sizeof(long long), "a long count holds every parsed integer");
        ParameterSpec spec =
            ParameterSpec::integer(std::move(name), default_of(field), std::move(unit), std::move(meaning));
        spec.max = static_cast<double>(std::numeric_limits<long>::max());
        return bind(field, std::move(spec), [](const Parameters& p, const std::string& key) {
            return static_cast<long>(p.integer(key));
        });
    }

    // A random seed, 0 to 2^63 - 1 (ParameterSpec::seed), so the cast to unsigned keeps its value.
    template <Field<Options, std::uint64_t> F>
    ParameterSpec& seed(F field, std::string name, std::string meaning)
    {
        return bind(field,
                    ParameterSpec::seed(std::move(name), static_cast<long long>(default_of(field)),
                                        std::move(meaning)),
                    [](const Parameters& p, const std::string& key) {
                        return static_cast<std::uint64_t>(p.integer(key));
                    });
    }

    // A real a keyword may stand for (ParameterSpec::keyword_allowed: a value the run computes, e.g. A0 = min):
    // the field holds the number, or nothing for the keyword, which is the default when the field's is nothing.
    template <Field<Options, std::optional<double>> F>
    ParameterSpec& real_or_keyword(F field, std::string name, std::string keyword, std::string unit,
                                   std::string meaning)
    {
        const std::optional<double> fallback = default_of(field);
        ParameterSpec spec =
            ParameterSpec::real(std::move(name), fallback.value_or(0.0), std::move(unit), std::move(meaning));
        if (fallback)
            spec.keyword_allowed(std::move(keyword));
        else
            spec.keyword_by_default(std::move(keyword));
        return bind(field, std::move(spec),
                    [](const Parameters& p, const std::string& key) -> std::optional<double> {
                        if (p.keyword(key)) return std::nullopt; // the one keyword the spec allows
                        return p.real(key);
                    });
    }

    template <Field<Options, bool> F>
    ParameterSpec& boolean(F field, std::string name, std::string meaning)
    {
        return bind(field, ParameterSpec::boolean(std::move(name), default_of(field), std::move(meaning)),
                    [](const Parameters& p, const std::string& key) { return p.boolean(key); });
    }

    // A choice: `names` lists every value the field can take (an enum, or a bool) with the word a user
    // types for it; the library then never compares strings.
    template <class F>
    requires Field<F, Options, FieldValue<F>> ParameterSpec&
    choice(F field, std::string name, std::vector<std::pair<std::string, FieldValue<F>>> names,
           std::string meaning)
    {
        std::vector<std::string> words;
        std::string default_word;
        for (const auto& [word, value] : names) {
            words.push_back(word);
            if (value == default_of(field)) default_word = word;
        }
        if (default_word.empty())
            throw std::logic_error("OptionBinding: the default of '" + name +
                                   "' has no name among its choices");
        return bind(
            field, ParameterSpec::choice(std::move(name), default_word, std::move(words), std::move(meaning)),
            [names](const Parameters& p, const std::string& key) {
                const std::string& word = p.choice(key); // one of the names: the spec checked it
                for (const auto& [candidate, value] : names)
                    if (candidate == word) return value;
                throw std::logic_error("OptionBinding: '" + key + "' = '" + word + "' has no value");
            });
    }

    // A choice kept as the word itself, for a library that looks its value up by name (a mesh by its name).
    template <Field<Options, std::string> F>
    ParameterSpec& word(F field, std::string name, std::vector<std::string> words, std::string meaning)
    {
        return bind(
            field,
            ParameterSpec::choice(std::move(name), default_of(field), std::move(words), std::move(meaning)),
            [](const Parameters& p, const std::string& key) { return p.choice(key); });
    }

    // A check across parameters, run on the filled options before the scene starts; it throws InputError
    // naming the keys involved.
    OptionBinding& check(Check cross_check)
    {
        checks_.push_back(std::move(cross_check));
        return *this;
    }

    const std::vector<ParameterSpec>& specs() const { return specs_; }

    // The options of one run: the defaults, each bound field read from `p` (already range-checked by its
    // spec), then the cross-parameter checks.
    Options read(const Parameters& p) const
    {
        Options options = filled(p);
        for (const Check& cross_check : checks_)
            cross_check(options);
        return options;
    }

    // The run's memory estimate (Scene::needing) from the filled options, so that it reads each parameter
    // through its binding rather than by name again:
    // scene.needing(binding.estimate([](const Options& options) { return ...; })).
    // The cross-parameter checks are left to the run: an absurd size is refused for its memory first, as
    // before any other check.
    template <class Estimate>
    std::function<MemoryEstimate(const Parameters&)> estimate(Estimate of_options) const
    {
        return [binding = *this, of_options](const Parameters& parameters) {
            return of_options(binding.filled(parameters));
        };
    }

  private:
    using Reader = std::function<void(const Parameters&, const std::string&, Options&)>;

    // The defaults with each bound field read from `p`.
    Options filled(const Parameters& p) const
    {
        Options options = defaults_;
        for (std::size_t k = 0; k < specs_.size(); ++k)
            readers_[k](p, specs_[k].name, options);
        return options;
    }

    template <class F>
    auto default_of(F field) const
    {
        Options copy = defaults_;
        return std::invoke(field, copy);
    }

    // Declares `spec` and how its value reaches `field`: read_value(p, name) converts the checked value.
    template <class F, class ReadValue>
    ParameterSpec& bind(F field, ParameterSpec spec, ReadValue read_value)
    {
        for (const ParameterSpec& existing : specs_)
            if (existing.name == spec.name)
                throw std::logic_error("OptionBinding: parameter '" + spec.name + "' declared twice");
        specs_.push_back(std::move(spec));
        readers_.push_back(
            [field, read_value](const Parameters& p, const std::string& key, Options& options) {
                std::invoke(field, options) = read_value(p, key);
            });
        return specs_.back();
    }

    Options defaults_;
    std::vector<ParameterSpec> specs_;
    std::vector<Reader> readers_;
    std::vector<Check> checks_;
};

// A scene whose parameters are `binding`'s and whose run takes the filled, checked options.
template <class Options>
Scene bound_scene(std::string name, std::string description, OptionBinding<Options> binding,
                  void (*run)(const Options&, RunContext&))
{
    std::vector<ParameterSpec> specs = binding.specs();
    return Scene{std::move(name), std::move(description), std::move(specs),
                 [binding = std::move(binding), run](const Parameters& p, RunContext& context) {
                     run(binding.read(p), context);
                 }};
}

} // namespace softgrain
