#include "dpm/protocols/single_particle.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <string>

namespace softgrain::dpm {

SingleParticle single_particle_equilibrium(ShapeModel model, int n, double a0, double A0,
                                           const ShapeStiffness& k, std::uint64_t seed)
{
    SingleParticle out;
    const ShapeParameters shape = table_9_1_parameters(model, n, a0, A0, k);
    out.system.add_particle(regular_polygon(n, regular_polygon_radius(n, a0), Eigen::Vector2d::Zero(), 0.0),
                            0.0, shape, out.x);
    Rng rng(seed);
    if (model == ShapeModel::floppy)
        for (Eigen::Index i = 0; i < out.x.size(); ++i)
            out.x(i) += 0.05 * shape.l0 * rng.normal(1.0);

    FireOptions fire;
    fire.force_tolerance = 1e-9;
    fire.dt_max = 0.05;
    const FireResult relaxed = relax_fire(out.system, out.x, fire);
    out.fire_iterations = relaxed.iterations;
    if (!relaxed.converged)
        throw NumericalError("relaxation of a single particle (" + fire_shortfall(relaxed, fire) + ")",
                             relaxed.iterations, "stiffnesses too disparate for the FIRE step dt_max = 0.05");
    const int newton_steps = 30;
    out.force_max = polish_newton(out.system, out.x, 1e-14, newton_steps);
    if (out.force_max > 1e-12)
        throw NumericalError("Newton polish of a single-particle equilibrium (max force " +
                                 std::to_string(out.force_max) + ")",
                             newton_steps, "no isolated equilibrium near the FIRE state");
    return out;
}

} // namespace softgrain::dpm
