#include "dpm/protocols/packing.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace softgrain::dpm {

Packing jam_packing(const PackingOptions& options)
{
    const double pi = std::numbers::pi, sigma = 1.0, R = options.C * sigma;
    const int n = options.nodes;
    const double a0 = 0.5 * n * R * R * std::sin(2 * pi / n);
    ShapeStiffness k;
    k.ka = options.ka * sigma * sigma / (a0 * a0);
    k.kl = options.kl;
    k.kb = options.kb * sigma * sigma;
    const ShapeParameters shape =
        table_9_1_parameters(options.model, n, a0, options.A0.value_or(minimum_shape_parameter(n)), k);

    Packing out;
    DpmSystem& s = out.system;
    s.interaction = options.interaction;
    s.kc = 1.0;
    const double L = std::sqrt(options.particles * a0 / options.phi_start);
    s.box = Eigen::Vector2d(L, L);
    Rng rng(options.seed);
    std::vector<Eigen::Vector2d> centres;
    const double exclusion = 2 * R + sigma;
    for (int m = 0; m < options.particles; ++m) {
        Eigen::Vector2d c;
        int tries = 0;
        bool free = false;
        while (!free) {
            if (++tries > 100000)
                throw InputError("phi_start = " + std::to_string(options.phi_start) +
                                 ": no room to place the particles without overlap; lower it");
            c = Eigen::Vector2d(rng.uniform(0, L), rng.uniform(0, L));
            free = true;
            for (const auto& other : centres)
                if (minimum_image(c - other, *s.box).norm() < exclusion) free = false;
        }
        centres.push_back(c);
        s.add_particle(regular_polygon(n, R, c, rng.uniform(0, 2 * pi)), sigma, shape, out.x);
    }

    FireOptions fire;
    fire.dt_max = 1.0 / std::sqrt(vibrational_modes(s, out.x).eigenvalues.maxCoeff());
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-12;
    double step = 1e-2; // Delta L / L
    const int max_steps = 100000;
    for (; out.compression_steps < max_steps; ++out.compression_steps) {
        const Eigen::VectorXd saved_x = out.x;
        const Eigen::Vector2d saved_box = *s.box;
        scale_packing(s, out.x, 1.0 - step);
        const FireResult r = relax_fire(s, out.x, fire);
        out.fire_iterations += r.iterations;
        if (!r.converged)
            throw NumericalError("relaxation during compression (" + fire_shortfall(r, fire) + ")",
                                 out.compression_steps,
                                 "too large a compression step for the FIRE time step");
        const double per_particle = r.energy / options.particles;
        if (per_particle > 2 * options.energy_onset) { // overshoot: undo and halve the step
            out.x = saved_x;
            *s.box = saved_box;
            step *= 0.5;
            if (step < 1e-14)
                throw NumericalError("compression step below 1e-14 without reaching the onset window",
                                     out.compression_steps, "energy_onset window too narrow for round-off");
            continue;
        }
        if (per_particle > options.energy_onset) return out;
    }
    throw NumericalError("jamming onset not reached", max_steps,
                         "phi_start too low or onset energy too high");
}

} // namespace softgrain::dpm
