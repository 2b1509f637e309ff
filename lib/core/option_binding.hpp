// Scene parameters declared once, bound to the field of the options struct they fill.
//
// A scene's options are a plain struct whose member initialisers are the defaults. The binding names each
// field once, with its unit, meaning and allowed range; from that one declaration it makes the
// ParameterSpecs that `describe` prints and the run checks (the defaults are read from the struct, never
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
#include "core/scene.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace softgrain {

template <class Options>
class OptionBinding
{
  public:
    using Check = std::function<void(const Options&)>;

    ParameterSpec& real(double Options::*field, std::string name, std::string unit, std::string meaning)
    {
        return bind(
            ParameterSpec::real(std::move(name), defaults().*field, std::move(unit), std::move(meaning)),
            [field](const Parameters& p, const std::string& key, Options& o) { o.*field = p.real(key); });
    }

    // An int field: its spec refuses values above INT_MAX (ParameterSpec::integer), so the cast cannot narrow.
    ParameterSpec& integer(int Options::*field, std::string name, std::string unit, std::string meaning)
    {
        return bind(
            ParameterSpec::integer(std::move(name), defaults().*field, std::move(unit), std::move(meaning)),
            [field](const Parameters& p, const std::string& key, Options& o) {
                o.*field = static_cast<int>(p.integer(key));
            });
    }

    // A long field (step counts): the whole range of a long, which is that of the parsed long long here.
    ParameterSpec& count(long Options::*field, std::string name, std::string unit, std::string meaning)
    {
        static_assert(sizeof(long) == sizeof(long long), "a long count holds every parsed integer");
        ParameterSpec spec =
            ParameterSpec::integer(std::move(name), defaults().*field, std::move(unit), std::move(meaning));
        spec.max = static_cast<double>(std::numeric_limits<long>::max());
        return bind(std::move(spec), [field](const Parameters& p, const std::string& key, Options& o) {
            o.*field = static_cast<long>(p.integer(key));
        });
    }

    ParameterSpec& seed(std::uint64_t Options::*field, std::string name, std::string meaning)
    {
        return bind(ParameterSpec::seed(std::move(name), static_cast<long long>(defaults().*field),
                                        std::move(meaning)),
                    [field](const Parameters& p, const std::string& key, Options& o) {
                        o.*field = static_cast<std::uint64_t>(p.integer(key)); // a seed spec is >= 0
                    });
    }

    ParameterSpec& boolean(bool Options::*field, std::string name, std::string meaning)
    {
        return bind(
            ParameterSpec::boolean(std::move(name), defaults().*field, std::move(meaning)),
            [field](const Parameters& p, const std::string& key, Options& o) { o.*field = p.boolean(key); });
    }

    // A choice parsed into an enum: `names` lists every value with the word a user types for it.
    template <class Enum>
    ParameterSpec& choice(Enum Options::*field, std::string name,
                          std::vector<std::pair<std::string, Enum>> names, std::string meaning)
    {
        std::vector<std::string> words;
        std::string default_word;
        for (const auto& [word, value] : names) {
            words.push_back(word);
            if (value == defaults().*field) default_word = word;
        }
        if (default_word.empty())
            throw std::logic_error("OptionBinding: the default of '" + name +
                                   "' has no name among its choices");
        return bind(
            ParameterSpec::choice(std::move(name), default_word, std::move(words), std::move(meaning)),
            [field, names](const Parameters& p, const std::string& key, Options& o) {
                const std::string& word = p.choice(key); // one of the names: the spec checked it
                for (const auto& [candidate, value] : names)
                    if (candidate == word) o.*field = value;
            });
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
        Options options{};
        for (std::size_t k = 0; k < specs_.size(); ++k)
            readers_[k](p, specs_[k].name, options);
        for (const Check& cross_check : checks_)
            cross_check(options);
        return options;
    }

  private:
    using Reader = std::function<void(const Parameters&, const std::string&, Options&)>;

    static const Options& defaults()
    {
        static const Options options{};
        return options;
    }

    ParameterSpec& bind(ParameterSpec spec, Reader reader)
    {
        for (const ParameterSpec& existing : specs_)
            if (existing.name == spec.name)
                throw std::logic_error("OptionBinding: parameter '" + spec.name + "' declared twice");
        specs_.push_back(std::move(spec));
        readers_.push_back(std::move(reader));
        return specs_.back();
    }

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
