#include "core/rng.hpp"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

namespace softgrain {

void Rng::Deleter::operator()(gsl_rng* r) const
{
    gsl_rng_free(r);
}

Rng::Rng(std::uint64_t seed) : generator_(gsl_rng_alloc(gsl_rng_mt19937)), seed_(seed)
{
    gsl_rng_set(generator_.get(), static_cast<unsigned long>(seed));
}

Rng::~Rng() = default;
Rng::Rng(Rng&&) noexcept = default;
Rng& Rng::operator=(Rng&&) noexcept = default;

double Rng::uniform()
{
    return gsl_rng_uniform(generator_.get());
}

double Rng::uniform(double low, double high)
{
    return low + (high - low) * uniform();
}

double Rng::normal(double standard_deviation)
{
    return gsl_ran_gaussian(generator_.get(), standard_deviation);
}

} // namespace softgrain
