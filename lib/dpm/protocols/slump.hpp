// Slump test of deformable particles under gravity, DPM Fig. 9.3 (section 9.2): bidisperse rough or smooth
// elastic shells settle in a box with frictionless side walls and a frictional floor; the right wall is
// then removed and damped molecular dynamics runs until the pile is at rest.
//
// Forces on vertex v (unit vertex mass m = 1, vertex diameter sigma = 1, k_c = 1):
//   shape (eq. 9.1) and rough (eqs. 9.3-9.4) or smooth (eqs. 9.5-9.9) repulsion: -grad U_DP;
//   walls: the plate law of section 9.3.4 with k_p = k_c, k_c/2 (sigma/2 - gap)^2 per vertex (WallEnergy);
//   gravity: -m g y^;
//   floor friction (decision dpm-slump-floor-friction), the paper gives no law: a tangential spring per
//     vertex touching the floor, F_t = -k_t (x - x_anchor), capped at mu_w F_n (Coulomb); on slip the
//     anchor follows so that |F_t| = mu_w F_n; the anchor is forgotten when the vertex leaves the floor.
//     A particle under a tangential load T stays (displacement T/(k_t n_c)) if T < mu_w W, slides if
//     T > mu_w W (W = weight carried by the floor vertices);
//   damping: -c v on every vertex (absolute viscous damping, decision dpm-slump-damping).
// Velocity Verlet with the half-step velocity in the damping force.
// Rest criterion: every particle's unbalanced force |sum_v F_v| (damping excluded) is below
// rest_tolerance times its weight n_mu m g; checked every 50 steps.
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace softgrain::dpm {

struct SlumpOptions
{
    InteractionKind interaction = InteractionKind::rough;
    int particles = 40;                     // 50:50 bidisperse, outer diameter ratio 1.4
    int nodes_small = 12, nodes_large = 16; // N_mu of the small and large particles
    double box_width = 5;                   // confining box width [D, mean outer particle diameter]
    double gravity = 2e-4;                  // g [k_c sigma / m]
    double wall_friction = 0.1;             // mu_w of the floor
    double tangential_stiffness = 1;        // k_t of the floor spring [k_c]
    double damping = 2e-3;                  // c [sqrt(m k_c)]
    double rest_tolerance = 1e-3;           // unbalanced force / particle weight at rest
    long max_steps = 2000000;               // cap per stage
    std::uint64_t seed = 1;
};

// One vertex's tangential floor spring: its anchor x, NaN when the vertex does not touch the floor.
struct FloorContacts
{
    std::vector<double> anchor;
};

// Wall forces on the pile, summed over vertices.
struct WallForces
{
    double floor_normal = 0;    // vertical force of the floor on the particles [k_c sigma]
    double floor_friction = 0;  // horizontal force of the floor on the particles
    double left = 0, right = 0; // horizontal forces of the side walls (left > 0, right < 0)
};

// Geometry of the dynamics: walls and the laws above.
struct SlumpWorld
{
    double gravity = 0, wall_friction = 0, tangential_stiffness = 1, damping = 0;
    double right_wall = 0; // x of the right wall; +inf: removed
    bool left_wall = true;
    double body_force_x = 0; // horizontal load on every vertex [k_c sigma] (tests of the floor law)
};

// Force on every vertex (without damping) at positions x; updates the floor springs; adds the wall forces.
void slump_forces(const DpmSystem& system, const SlumpWorld& world, const Eigen::VectorXd& x,
                  FloorContacts& floor, Eigen::VectorXd& force, WallForces* walls);

struct RestResult
{
    long steps = 0;
    double unbalanced = 0; // max over particles of |F_net| / weight at the end
    WallForces walls;
};

// Sees the state after each time step: the system, the world, positions, velocities, the steps taken in all
// stages and the time they span [time unit sqrt(m/k_c)].
using SlumpObserver = std::function<void(const DpmSystem&, const SlumpWorld&, const Eigen::VectorXd& x,
                                         const Eigen::VectorXd& v, long step, double time)>;

// Damped MD from x, v until at rest (rest_tolerance) or NumericalError after max_steps. observe, if given,
// sees each step, numbered from steps_before + 1.
RestResult run_to_rest(const DpmSystem& system, const SlumpWorld& world, Eigen::VectorXd& x,
                       Eigen::VectorXd& v, FloorContacts& floor, double dt, double rest_tolerance,
                       long max_steps, const char* stage, const SlumpObserver& observe = {},
                       long steps_before = 0);

// Largest stable time step estimate: 0.2/omega_max of the stiffest particle plus its contacts.
double slump_time_step(const DpmSystem& system, const Eigen::VectorXd& x);

struct SlumpStage
{
    Eigen::VectorXd x;
    RestResult rest;
};

struct SlumpResult
{
    DpmSystem system;
    SlumpStage confined, released;
    double diameter = 0;  // mean outer diameter D [sigma]
    double box_width = 0; // [sigma]
    double dt = 0;
};

// observe, if given, sees the initial state (step 0) and every step of both stages.
SlumpResult run_slump(const SlumpOptions& options, const SlumpObserver& observe = {});

// Free surface: topmost vertex height (+ sigma/2) in bins of width `bin` from x = 0; NaN for empty bins.
std::vector<double> surface_profile(const Eigen::VectorXd& x, double bin);
// The free surface in units of D: the heights of the occupied bins of width D (surface_profile over D) at
// their centres, and the least-squares line through them (0, 0 below two bins); its slope gives the angle
// of repose.
struct SurfaceFit
{
    std::vector<double> centre, height; // occupied bins [D]
    double intercept = 0, slope = 0;    // height = intercept + slope centre
};
SurfaceFit fit_free_surface(const Eigen::VectorXd& x, double diameter);
// Right edge of the pile: largest vertex x + sigma/2.
double pile_front(const Eigen::VectorXd& x);
// Particles cut by the vertical line at `at` (number of layers there).
int particles_crossing(const DpmSystem& system, const Eigen::VectorXd& x, double at);

} // namespace softgrain::dpm
