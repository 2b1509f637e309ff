// The parameters every VSM scene shares (material, internal force, contact factor, seed, time-step check),
// bound once here with the meaning `describe` prints; each scene's defaults come from its own options.
#pragma once

#include "core/option_binding.hpp"
#include "core/resources.hpp"
#include "vsm/vsm_model.hpp"

#include <string>

namespace softgrain::vsm {

// E, nu, rho of the neo-Hookean material, eq. (48).
template <class Options, class MaterialField>
void bind_material(OptionBinding<Options>& binding, MaterialField material)
{
    binding.real(path(material, &Material::young), "E", "Pa", "Young's modulus").positive();
    binding.real(path(material, &Material::poisson), "nu", "1", "Poisson's ratio").at_least(-0.99).below(0.5);
    binding.real(path(material, &Material::density), "rho", "kg/m^3", "density").positive();
}

template <class Options, class Field>
void bind_jitter_seed(OptionBinding<Options>& binding, Field seed)
{
    binding.seed(seed, "seed", "seed of the jitter");
}

template <class Options, class Field>
void bind_internal_force(OptionBinding<Options>& binding, Field internal)
{
    binding.choice(internal, "internal_force", {{"eq41", InternalForce::eq41}, {"eq43", InternalForce::eq43}},
                   "internal force: eq41 = eq. (41) in its pairwise form (42) with reactions (static "
                   "form), eq43 = angular-momentum-preserving eq. (43)");
}

// One parameter `xi` sets both contact factors xi_n = xi_t of eq. (50) (with_contact_factors below).
template <class Options, class Field>
void bind_contact_factor(OptionBinding<Options>& binding, Field xi,
                         std::string meaning = "contact factors xi_n = xi_t of eq. (50)")
{
    binding.real(xi, "xi", "1", std::move(meaning)).non_negative();
}

inline ModelOptions with_contact_factors(ModelOptions options, double xi)
{
    options.xi_n = xi;
    options.xi_t = xi;
    return options;
}

template <class Options, class Field>
void bind_time_step_check(OptionBinding<Options>& binding, Field check)
{
    binding.boolean(check, "time_step_check",
                    "refuse a time step above the predicted stability limit C_stab L_min / c_eff "
                    "(vsm/stability.hpp) before the run (exit 3); false only for stability "
                    "studies");
}

// The memory of a VSM body of `particles` particles: 13 kB per particle, measured as the growth of peak RSS
// between vsm.patch runs of 6^3 and 14^3 particles (Voronoi cells, neighbour lists, the matrices K'_a).
inline MemoryEstimate vsm_particle_memory(double particles, const std::string& what)
{
    return per_item_memory(particles, 13e3, what);
}

// x^3: the particles of a cube of x particles on a side, or the volume of a cube of side x.
inline double cube(double x)
{
    return x * x * x;
}

} // namespace softgrain::vsm
