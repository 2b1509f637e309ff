// Seeded random numbers (GSL's MT19937: the same stream on every platform for a given seed). A scene
// that draws random numbers records its seed in summary.json (RunContext::record_seed).
#pragma once

#include <cstdint>
#include <memory>

#include <gsl/gsl_rng.h>

namespace softgrain {

class Rng
{
  public:
    explicit Rng(std::uint64_t seed);
    ~Rng();
    Rng(Rng&&) noexcept;
    Rng& operator=(Rng&&) noexcept;

    double uniform();                         // in [0, 1)
    double uniform(double low, double high);  // in [low, high)
    double normal(double standard_deviation); // zero mean
    std::uint64_t seed() const { return seed_; }

  private:
    struct Deleter
    {
        void operator()(gsl_rng* r) const;
    };
    std::unique_ptr<gsl_rng, Deleter> generator_;
    std::uint64_t seed_;
};

} // namespace softgrain
