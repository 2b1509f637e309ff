#include "spd/beam.hpp"
#include "core/step_count.hpp"

#include "core/errors.hpp"
#include "spd/shell_model.hpp"
#include "spd/time_step_limits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::spd {

double beam_flexural_rigidity(const BeamSetup& setup)
{
    const double l = setup.length / (setup.nodes - 1);
    return calibrate(setup.material, l).k_b * l;
}

double beam_deflection_max_theory(const BeamSetup& setup)
{
    const double L3 = std::pow(setup.length, 3);
    const double EI = beam_flexural_rigidity(setup);
    return setup.support == BeamSupport::cantilever ? setup.force * L3 / (3.0 * EI)
                                                    : setup.force * L3 / (48.0 * EI);
}

double cantilever_shape(double xi)
{
    return 0.5 * xi * xi * (3.0 - xi);
}
double simple_point_load_shape(double xi)
{
    const double z = std::min(xi, 1.0 - xi);
    return 3.0 * z - 4.0 * z * z * z;
}
double simple_uniform_load_shape_eq16(double xi)
{
    return 16.0 / 5.0 * xi * (1.0 - 2.0 * xi * xi + xi * xi * xi);
}

double beam_discrete_ratio(BeamSupport support, int nodes)
{
    const double n = nodes - 1;
    return support == BeamSupport::cantilever ? (n + 1) * (2 * n + 1) / (2 * n * n) : 1.0 + 2.0 / (n * n);
}

BeamResult simulate_beam(const BeamSetup& setup, double dt_factor, double force_tolerance_relative,
                         const BeamObserver& observe)
{
    const bool cantilever = setup.support == BeamSupport::cantilever;
    if (setup.nodes < 3)
        throw InputError("nodes = " + std::to_string(setup.nodes) + ": a beam needs at least 3");
    if (!cantilever && setup.nodes % 2 == 0)
        throw InputError("nodes = " + std::to_string(setup.nodes) +
                         ": the simply supported beam is loaded at its centre node, so nodes must be odd");
    const double l = setup.length / (setup.nodes - 1);
    const int ghost = cantilever ? 1 : 0; // the clamp: a frozen node one element inside the wall
    Points<2> vertices(2, setup.nodes + ghost);
    for (int k = 0; k < setup.nodes + ghost; ++k)
        vertices.col(k) = Vec2((k - ghost) * l, 0.0);

    ShellModel model;
    Shell shell;
    shell.closed = false;
    shell.laws = calibrate(setup.material, l);
    shell.depth = setup.material.s;
    const double m = 1.0; // static problem: the mass only sets the time scale
    model.add_shell(vertices, shell, m);
    const int load = cantilever ? setup.nodes : ghost + setup.nodes / 2;
    if (cantilever) {
        for (int c : {0, 1})
            model.freeze(0, c), model.freeze(1, c);
    } else {
        model.freeze(0, 0), model.freeze(0, 1), model.freeze(setup.nodes - 1, 1);
    }

    // Fundamental bending frequency omega_1 = beta^2 sqrt(EI / (rho L^4)), rho = m / l;
    // beta L = 1.875 (cantilever), pi (simply supported). Damping c = 2 m omega_1 (critical for that mode).
    const double EI = beam_flexural_rigidity(setup);
    const double beta_L = cantilever ? 1.8751 : std::numbers::pi;
    const double omega1 = beta_L * beta_L * std::sqrt(EI * l / (m * std::pow(setup.length, 4)));
    BeamResult r;
    r.critical_time_step = critical_time_step(model);
    r.dt = dt_factor * r.critical_time_step;
    check_time_step(model, r.dt);

    model.set_applied_force(load, Vec2(0.0, -setup.force));
    const long max_steps = checked_step_count(std::floor(200.0 * 2 * std::numbers::pi / (omega1 * r.dt)),
                                              "the relaxation budget", "dt_factor", dt_factor) +
                           10000;
    std::function<void(long)> after_check;
    if (observe) {
        observe(model, 0, false);
        after_check = [&](long n) { observe(model, n, false); };
    }
    r.steps = relax(model, r.dt, 2.0 * m * omega1, force_tolerance_relative * setup.force, max_steps, 0,
                    after_check);
    if (observe) observe(model, r.steps, true);
    for (int k = 0; k < setup.nodes; ++k) {
        r.x.push_back(model.vertex(ghost + k).x());
        r.deflection.push_back(-model.vertex(ghost + k).y());
    }
    r.deflection_max = *std::max_element(r.deflection.begin(), r.deflection.end());
    return r;
}

} // namespace softgrain::spd
