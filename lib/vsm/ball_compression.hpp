// A VSM ball compressed between two rigid frictionless plates (compare.solid, issue 22; not a figure of the
// paper): the Hertz problem that the DPM bodies and the finite-element ball of data/compare/solid_fe.toml
// solve, posed to VSM.
//
// The ball |X| < R (D = 2R) is modelled by its octant X1, X2, X3 >= 0: the planes X1 = 0 and X2 = 0 are
// planes of symmetry of the problem and X3 = 0 its mid-plane between the plates, all symmetric boundaries of
// eq. (14) (zero normal displacement), as in the finite-element reference. Particles sit on a cell-centred
// cubic lattice of spacing h = R / per_radius, those with |X| <= R - h/2; the sphere gets its ghosts across
// the tangent planes (reference_cells.hpp). The top plate is a RigidPlate on the spherical surface at
// height R - delta/2; it is lowered in `compressions` log-spaced steps from delta_min D to delta_max D, each
// at the speed plate_speed c_s (a plate jumping by a step would strike the ball: the impact inverts surface
// particles at fine resolution), and after each the ball is relaxed by damped leapfrog until both the unbalanced force and the damping force
// of every particle are below relax_tolerance times the plate load. The full plate force is four times the
// octant's. Units: SI (m, Pa, kg/m^3, s, N).
#pragma once

#include "vsm/vsm_model.hpp"

#include <functional>
#include <vector>

namespace softgrain::vsm {

struct BallCompressionSetup
{
    int per_radius = 8; // lattice spacing h = R / per_radius
    double diameter = 1.0;
    Material material{1.0e6, 0.3, 1.0e3};
    ModelOptions options{InternalForce::eq43, 1.0, 1.0, 0.0, 0.0};
    double penalty = 25; // c_pen of RigidPlate: kappa_ab = c_pen E / L_ab
    double delta_min = 1e-3, delta_max = 0.2;
    int compressions = 24;
    double plate_speed = 0.01; // the plate moves between compressions at this times c_s (no impact)
    double relax_tolerance = 1e-3;
    double damping = 4; // mass-proportional damping c, in units of c_s / R
    double cfl = 0.3;   // dt = cfl min(L_min / c_eff, sqrt(m_a / k_ab)) over the particles and plate springs
    bool time_step_check = true;
};

struct BallCompressionSample
{
    double delta_over_d = 0;
    double force = 0;    // load of the whole top plate [N]
    int contacts = 0;    // boundary points of the octant beyond the plate
    long steps = 0;      // leapfrog steps of this compression
    double residual = 0; // largest unbalanced force over the load at the end of the relaxation
};

struct BallCompressionResult
{
    int particles = 0;
    double dt = 0;
    double dt_elastic_limit = 0; // predicted limit C_stab L_min / c_eff (vsm/stability.hpp) [s]
    double volume_excess = 0;    // sum V_a over the octant's volume, minus 1
    long steps = 0;
    std::vector<BallCompressionSample> samples;
};

// Cell-centred cubic lattice of spacing h = R / per_radius in the octant, the points with |X| <= R - h/2: the
// outermost particles lie at least half a spacing inside the sphere, as a lattice's particles do from a flat
// face.
Points<3> octant_lattice(double R, int per_radius);

// The compressions delta / D: `compressions` values log-spaced from delta_min to delta_max.
std::vector<double> ball_compressions(const BallCompressionSetup& setup);

// Runs the protocol; observe, if given, sees each sample as it is taken. Throws NumericalError (exit 3)
// when a particle inverts or a relaxation does not converge within its step budget.
BallCompressionResult compress_ball(const BallCompressionSetup& setup,
                                    const std::function<void(const BallCompressionSample&)>& observe = {});

} // namespace softgrain::vsm
