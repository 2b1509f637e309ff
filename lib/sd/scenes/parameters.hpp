// What the SD scenes share: their units, the pair problem of the paper and the integration parameters of
// sd.approach and sd.phase_diagram, bound once here.
//
// Units of every scene: R = eta = E = 1 and F_ext = kappa, so that lengths are in R, forces in E R^2,
// velocities in V = F_ext/(eta R) (eq. 6) after division by kappa, and times in R/V.
#pragma once

#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "sd/approach.hpp"

#include <string>
#include <vector>

namespace softgrain::sd {

// The approach of two spheres of the paper's material and laws under constant loading kappa, from h0 to
// h_min.
inline ApproachProblem pair_problem(double kappa, double h0, double h_min)
{
    const Material material; // R = E = eta = 1, alpha = 4/9
    if (!(h_min < h0))
        throw InputError("h_min = " + std::to_string(h_min) + " must be below h0 = " + std::to_string(h0));
    return {material, paper_contact_laws(material), constant_loading(kappa), h0, h_min};
}

inline std::vector<std::string> stepper_names()
{
    std::vector<std::string> names;
    for (const Stepper& stepper : gsl_steppers())
        names.push_back(stepper.name);
    return names;
}

// The integration parameters sd.approach and sd.phase_diagram share. The default stepper is the cheapest
// that meets the accuracy on the Hertz regime (see reproductions/sd, sd-work-precision, and
// data/sd/decisions.toml, sd-default-stepper).
struct IntegratorChoice
{
    std::string stepper = "rk8pd";
    double tolerance = 1e-10;
    int samples_per_decade = 20;
    double regime_width = 0.1;
};

template <class Options>
void bind_integrator(OptionBinding<Options>& binding, IntegratorChoice Options::*integrator)
{
    binding.word(path(integrator, &IntegratorChoice::stepper), "stepper", stepper_names(),
                 "GSL ODE stepper for eqs. (7), (9)");
    binding
        .real(path(integrator, &IntegratorChoice::tolerance), "tolerance", "1",
              "adaptive control: relative local error of h and delta per step")
        .positive()
        .below(1e-2);
    binding
        .integer(path(integrator, &IntegratorChoice::samples_per_decade), "samples_per_decade", "1",
                 "outputs per decade of h")
        .at_least(4);
    binding
        .real(path(integrator, &IntegratorChoice::regime_width), "regime_width", "1",
              "a regime counts as reached where its first-order width w (Stokes (R/h)(3 - 2R/(R + delta)), "
              "Poiseuille h/R + 3 delta/h, Hertz 3h/R + 4h/(3 delta)) is at most this")
        .positive()
        .below(1.0);
}

inline IntegratorSettings adaptive_settings(const IntegratorChoice& integrator)
{
    IntegratorSettings settings;
    settings.stepper = integrator.stepper;
    settings.tolerance = integrator.tolerance;
    settings.samples_per_decade = static_cast<double>(integrator.samples_per_decade);
    return settings;
}

} // namespace softgrain::sd
