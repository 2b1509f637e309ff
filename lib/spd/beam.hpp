// SPD section 3: calibration check on beams (Figs. 7-8). An open shell of N collinear nodes (reference
// angles 0), loaded by a point force F, relaxed to static equilibrium.
//
// Supports (decision spd-beam-supports): the cantilever's clamp is a rigid wall, i.e. node 0 and a frozen
// ghost node one element behind it, so node 0 carries a hinge spring k_b; the simply supported beam has a
// pin at node 0 and a roller at node N-1, without hinges at its ends (open shell), and F at the centre node
// (N odd).
#pragma once

#include "spd/calibration.hpp"

#include <functional>
#include <string>
#include <vector>

namespace softgrain::spd {

enum class BeamSupport { cantilever, simple };

struct BeamSetup
{
    BeamSupport support = BeamSupport::cantilever;
    int nodes = 21;
    ShellMaterial material;
    double length = 1; // L [m]
    double force = 0;  // F [N], transverse (downward)
};

// Flexural rigidity of the chain: EI_eff = k_b l = E I_c / (1 - nu^2) with I_c = h^3 l / 12 (eqs. (11),
// (15), decisions spd-Ic-width and spd-beam-plate-modulus).
double beam_flexural_rigidity(const BeamSetup& setup);

// Point-load theory (decision spd-eq16-17-point-load): cantilever, eq. (15) read F L^3/(3 EI);
// simply supported with a central point load, F L^3/(48 EI) (the printed eq. (17), 5 F L^3/(768 EI), is the
// uniform-load formula). EI = beam_flexural_rigidity.
double beam_deflection_max_theory(const BeamSetup& setup);

// Normalised shapes delta(x)/delta_max, xi = x/L: cantilever eq. (14) 1/2 xi^2 (3 - xi); simply supported
// under a central point load 3 xi - 4 xi^3 for xi <= 1/2 (symmetric); and the paper's eq. (16) as printed,
// (16/5) xi (1 - 2 xi^2 + xi^3), the uniform-load shape.
double cantilever_shape(double xi);
double simple_point_load_shape(double xi);
double simple_uniform_load_shape_eq16(double xi);

// Exact small-load discrete result of the hinge chain (rigid segments, hinge springs k_b, n = N - 1
// elements): cantilever with the clamp hinge, delta/delta_th = (n+1)(2n+1)/(2 n^2); simply supported,
// n even, 1 + 2/n^2.
double beam_discrete_ratio(BeamSupport support, int nodes);

struct BeamResult
{
    std::vector<double> x, deflection; // node positions along the beam and downward deflections [m]
    double deflection_max = 0;         // [m]
    double critical_time_step = 0, dt = 0;
    long steps = 0;
};

class ShellModel;
// Sees the beam (shell 0; the cantilever's clamp ghost node first) during the relaxation: at step 0 with the
// load applied, after each unsuccessful force check (every 16 steps) and, with relaxed = true, at the end.
using BeamObserver = std::function<void(const ShellModel& model, long step, bool relaxed)>;

// Relaxes the loaded beam with damped velocity Verlet (dt = dt_factor dt_c, damping critical for the
// fundamental mode) until the largest unbalanced force is below force_tolerance_relative * F. The residual
// deflection error grows with N (1e-5 F leaves 4e-4 at N = 129, 1e-6 F leaves 5e-5); the floor is the
// round-off accumulated by the incremental laws (~7e-7 F at N = 129, h = 0.05 m), hence the default 1e-6,
// valid up to N ~ 129 for such beams (a thinner or finer beam may need a larger value).
constexpr double beam_force_tolerance_relative = 1e-6;
BeamResult simulate_beam(const BeamSetup& setup, double dt_factor = 0.5,
                         double force_tolerance_relative = beam_force_tolerance_relative,
                         const BeamObserver& observe = {});

} // namespace softgrain::spd
