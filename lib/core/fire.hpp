// FIRE minimiser (Bitzek, Koskinen, Gähler, Moseler, Gumbsch, Phys. Rev. Lett. 97, 170201 (2006)).
//
// Damped molecular dynamics (velocity Verlet, unit masses) whose velocity is mixed towards the force,
// v <- (1 - alpha) v + alpha |v| F/|F|, with an adaptive step: after N_min downhill steps (P = F.v > 0)
// dt grows by f_inc up to dt_max and alpha shrinks by f_alpha; on an uphill step (P <= 0) the velocity is
// zeroed, dt shrinks by f_dec and alpha is reset. Parameter defaults are the paper's.
//
// Stopping rule: the root-mean-square force per degree of freedom is below `force_tolerance` AND the
// kinetic energy per degree of freedom is below `kinetic_tolerance`. Optionally FIRE stops early, unconverged,
// to hand over to another minimiser (`hand_over`, e.g. a Newton finisher where FIRE crawls).
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>

namespace softgrain {

struct FireOptions
{
    double dt_initial = 1e-2;
    double dt_max = 1e-1;
    double force_tolerance = 1e-10;   // [force]
    double kinetic_tolerance = 1e-20; // [energy] per degree of freedom
    long max_iterations = 1000000;
    int n_min = 5;
    double f_inc = 1.1;
    double f_dec = 0.5;
    double alpha_start = 0.1;
    double f_alpha = 0.99;
    // Called once per iteration, after the stopping rule, with the iteration and the force rms; FIRE stops
    // (handed_over, not converged) when it returns true. Empty: never.
    std::function<bool(long iteration, double force_rms)> hand_over;
};

struct FireResult
{
    bool converged = false;
    bool handed_over = false; // stopped by options.hand_over
    long iterations = 0;
    long force_evaluations = 0; // calls of energy_and_force: the start and one per iteration
    double seconds = 0;         // wall time of the relaxation (a cost, never asserted)
    double energy = 0;
    double force_rms = 0;
    double kinetic = 0; // kinetic energy per degree of freedom at the end
};

// energy_and_force(x, f) returns U(x) and writes f = -grad U(x).
using EnergyAndForce = std::function<double(const Eigen::VectorXd&, Eigen::VectorXd&)>;

FireResult fire_minimise(Eigen::VectorXd& x, const EnergyAndForce& energy_and_force,
                         const FireOptions& options);

// Why a relaxation stopped unconverged, for a diagnosis: the iterations and both stopping quantities
// against their tolerances, e.g. "FIRE stopped after 1000000 iterations: force rms 3.2e-12 (tolerance
// 1e-11), kinetic energy 4.1e-19 per degree of freedom (tolerance 1e-20)".
std::string fire_shortfall(const FireResult& result, const FireOptions& options);

} // namespace softgrain
