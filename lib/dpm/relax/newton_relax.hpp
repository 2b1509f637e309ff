// Relaxation of a DPM system, 2D (DpmSystem) or 3D (DpmSystem3d), to mechanical equilibrium (issue 19): FIRE
// alone, or FIRE that hands over to a regularised Newton finisher on the sparse dynamical matrix (eq. 9.28,
// sparse_dynamical_matrix and sparse_dynamical_matrix3d) where it crawls. One code for both dimensions: the
// dimension enters only through the system's energy, Hessian and touching pairs.
//
// Finisher (regularised Newton / Levenberg-Marquardt with a trust-region update of the shift: Li,
// Fukushima, Qi & Yamashita, Comput. Optim. Appl. 28, 131 (2004); Nocedal & Wright, Numerical Optimization,
// 2nd ed., secs. 4.1 and 10.3). At x with force F = -grad U and Hessian M (assembled sparse from the local
// terms, sparse_dynamical_matrix), the step dx solves (M + mu I) dx = F with Eigen's SimplicialLDLT.
//   Shift: mu = theta |F| / sigma (sigma the smallest vertex diameter, theta >= 1). The regularisation
//   mu ~ |grad U| of Li et al. keeps the convergence quadratic also where the minima form a manifold and M
//   is singular (the floppy shape modes, the rattlers' cages, the uniform translations), because the shift
//   vanishes with the force: it leaves a residual force of order |F|^2 / (sigma lambda). It is never below
//   n eps R (R = max row sum of |M| >= every |lambda|, Gershgorin), the round-off bound within which an
//   exact zero mode of M can come out negative. While a pivot of the LDL^T is <= 0 (M + mu I indefinite)
//   mu is multiplied by 10, up to 2 R (definite by Gershgorin); where that takes mu above 100 times the
//   shift, M has a curvature below -100 mu: x is on the way over a saddle (a rearrangement), not near a
//   minimum, and the finisher stops (FIRE's damped dynamics does better there).
//   Acceptance on the energy at the trial point x + dx, evaluated afresh with its own contacts (the
//   Verlet list rebuilds where vertices moved): a contact that forms or breaks in the step is outside M's
//   model and shows in U' and F'. A step is accepted when U' < U, rejected (x kept) when U' >= U; after a
//   rejection mu becomes 4 times the model's curvature along the rejected step, F.dx / |dx|^2 (which
//   shortens it about 4-fold; multiplying mu alone barely does while mu is far below M's eigenvalues along
//   dx). With rho = (U - U') / (F.dx - dx.M dx / 2) < 1/4 theta is multiplied by 4, with rho > 3/4 divided
//   by 4 (not below 1). Energy changes within the round-off of U (energy_round_off) cannot tell: such a
//   step is accepted only when it lowers |F| as well.
//   Stops: converged when the force rms is below FIRE's force tolerance (FIRE's force criterion; the
//   finisher's state has zero velocity, so FIRE's kinetic criterion holds trivially); unconverged (the
//   caller falls back to FIRE) after `max_steps` factorisations, `max_rejections` rejections in a row,
//   `max_slow_steps` accepted steps in a row that do not halve |F|, or at negative curvature (above).
//   NumericalError (exit 3) when U or F are not finite at the start or at a trial point, when M has a
//   non-finite entry, the LDL^T fails at mu = 2 R or the solve is not finite.
//
// Hand-over rule (FIRE -> finisher), from measurements on the issue-19 protocol (16 floppy particles of
// 16/22 vertices, A0 = 1.05, P_t = 1e-7 and 1e-6): a healthy FIRE relaxation takes 2000-5000 iterations and
// gains a decade of force in 100-300, from 100 tolerances to the tolerance in ~35 % of its iterations;
// one finisher step from below 100 tolerances reaches 1e-3 tolerances (1.4 ms, ~100 FIRE iterations).
// The crawls (30 000-1 000 000 iterations) spend most of their time between 1e4 and 1 tolerance. FIRE hands
// over when its force rms is below `handover_factor` (100) tolerances, or below `crawl_factor` (1e3) while
// its lowest force rms has not halved in the last `crawl_window` (2000) iterations. Handing over at 1e3
// tolerances, or on crawls below 1e4, was slower (the finisher fails more often there: contacts keep
// changing). After an unconverged finisher FIRE continues from the finisher's state (lower energy, zero
// velocity) for at least a crawl window, and hands over at most `max_handovers` (3) times per relaxation.
#pragma once

#include "core/fire.hpp"
#include "dpm/system/system.hpp"
#include "dpm/system/system3d.hpp"

#include <Eigen/SparseCore>
#include <concepts>
#include <string>
#include <vector>

namespace softgrain::dpm {

// The systems a relaxation takes: 2D or 3D.
template <class System>
concept RelaxableSystem = std::same_as<System, DpmSystem> || std::same_as<System, DpmSystem3d>;

// FIRE (core) on the total energy; returns its result. Iterations are the cost measure.
template <RelaxableSystem System>
FireResult relax_fire(const System& system, Eigen::VectorXd& x, const FireOptions& options);

enum class Relaxation { fire, fire_newton };
Relaxation relaxation_from_name(const std::string& name); // "fire" | "fire_newton"; InputError otherwise

struct NewtonOptions
{
    double force_tolerance = 0; // rms force per degree of freedom, FIRE's force_tolerance
    int max_steps = 60;         // factorised steps per call
    int max_rejections = 8;     // in a row
    int max_slow_steps = 8;     // accepted steps in a row that do not halve the force rms
};

struct NewtonResult
{
    bool converged = false;
    int steps = 0;              // accepted steps
    int rejections = 0;         // rejected trial steps
    int factorizations = 0;     // LDL^T factors computed
    int contact_changes = 0;    // accepted steps that changed the set of touching vertex pairs
    long force_evaluations = 0; // energy and gradient evaluations (trial points; a Hessian evaluation counts)
    double seconds = 0;
    double energy = 0, force_rms = 0;
    std::vector<double> energies, force_norms; // at the start and after each accepted step (|F|, 2-norm)
    std::string stop_reason;                   // why it stopped unconverged
};

// The regularised Newton step dx of (M + mu I) dx = F (sparse symmetric M, Eigen's SimplicialLDLT) with the
// smallest mu >= the given one (times 10 per try, at most 2 bound) at which the LDL^T has only positive
// pivots; mu becomes the one used, `factorizations` counts the factors. bound >= every |lambda| of M (the
// Gershgorin bound, sparse_modes.hpp), so M + 2 bound I is definite. NumericalError (naming `step_index`)
// when it is not, or when the step is not finite. Also the step of the sparse 3D Newton polish
// (packing_hessian3d.hpp).
Eigen::VectorXd regularised_newton_step(const Eigen::SparseMatrix<double>& hessian,
                                        const Eigen::VectorXd& force, double& mu, double bound,
                                        int& factorizations, int step_index);

// The finisher from x (x becomes the lowest-energy point reached).
template <RelaxableSystem System>
NewtonResult newton_finish(const System& system, Eigen::VectorXd& x, const NewtonOptions& options);

// Round-off of a difference of two computed total energies near x, measured: U is invariant under a rigid
// translation of every vertex (and anchor), so the change of the computed U under a translation (by
// irrational fractions of the smallest vertex diameter) is round-off alone, a sample of the spread s of such
// a difference. The bound is 6 times the rms of 8 samples plus 16 eps |U|: if such differences are normal,
// one exceeds it with probability 3e-4 (|t| > 6 for Student's t with 8 degrees of freedom, since the rms
// is itself a sample), and a false rejection costs the finisher one shortened step. Energy differences
// below it are noise. (One or two samples are not
// enough: on 4 shell icosahedra two of them gave 2.7e-18 where the differences the finisher met reached
// 1.1e-17, and it rejected 17 good steps; verification/dpm/relax/newton_relax.cpp.)
template <RelaxableSystem System>
double energy_round_off(const System& system, const Eigen::VectorXd& x, double energy);

struct RelaxOptions
{
    Relaxation method = Relaxation::fire;
    FireOptions fire;
    double handover_factor = 100; // hand over below this many force tolerances
    double crawl_factor = 1e3;    // or below this many while crawling
    long crawl_window = 2000;     // FIRE iterations without halving the lowest force rms: crawling
    int max_handovers = 3;
};

struct RelaxResult
{
    bool converged = false;
    long fire_iterations = 0;
    long force_evaluations = 0; // FIRE's: one per iteration and one at the start of each FIRE run
    int newton_steps = 0, factorizations = 0, handovers = 0;
    double seconds = 0, fire_seconds = 0, newton_seconds = 0;
    double energy = 0, force_rms = 0, kinetic = 0; // at the end (kinetic 0 after the finisher)
    FireResult last_fire;                          // of the last FIRE run, for fire_shortfall
    std::string newton_stop_reason;                // of the last unconverged finisher, if any
};

template <RelaxableSystem System>
RelaxResult relax(const System& system, Eigen::VectorXd& x, const RelaxOptions& options);

// What a protocol's relaxations cost, summed over them (the jamming protocols' results in 2D and 3D).
struct RelaxTally
{
    long fire_iterations = 0;
    long force_evaluations = 0; // energy and gradient evaluations of all FIRE runs
    double relax_seconds = 0;   // wall time of all relaxations (FIRE and the Newton finisher)
    double fire_seconds = 0;    // of which FIRE
    long newton_steps = 0;      // accepted steps of the Newton finisher (relaxation = fire_newton)
    long factorizations = 0;    // its sparse LDL^T factorisations
    long handovers = 0;         // relaxations FIRE handed over to it

    void add(const RelaxResult& r)
    {
        fire_iterations += r.fire_iterations;
        force_evaluations += r.force_evaluations;
        relax_seconds += r.seconds;
        fire_seconds += r.fire_seconds;
        newton_steps += r.newton_steps;
        factorizations += r.factorizations;
        handovers += r.handovers;
    }
};

// Why a relaxation stopped unconverged (fire_shortfall, and the finisher's last stop reason).
std::string relax_shortfall(const RelaxResult& result, const RelaxOptions& options);

} // namespace softgrain::dpm
