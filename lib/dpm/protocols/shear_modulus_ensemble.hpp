// The ensemble part of Fig. 9.16 (DPM sec. 9.4.3), shared by dpm.shear_modulus (2D) and dpm.shear_modulus3d:
// G at every pressure of a jamming run (shear_modulus.hpp), packings in parallel over threads and MPI ranks
// (core/ensemble.hpp), the ensemble means <P> and <G> per pressure level, and the exponent eta of
// <G> ~ P^eta (eq. 9.29 at large P): the least-squares slope of ln<G> against ln<P> over the levels above
// onset with <G> > 0 (decision dpm-shear-modulus).
#pragma once

#include "dpm/analysis/linear_shear_modulus.hpp"
#include "dpm/protocols/shear_modulus.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace softgrain {
class RunContext;
}

namespace softgrain::dpm {

// One packing of the ensemble: its pressures (onset first), packing fractions and shear moduli, in the
// model's pressure unit: `modulus` from the strain steps, `modulus_linear` the linear response at the
// same equilibrium (linear_shear_modulus.hpp), with the negative modes of its Hessian (a saddle), and the
// smallest normal stress over the pressure (smallest_normal_stress).
struct ModulusMember
{
    std::vector<double> pressure, phi, modulus, modulus_linear, normal_stress_min;
    std::vector<int> negative_modes;
    long fire_iterations = 0;
    double force_max = 0; // largest force after any Newton minimisation [system units]
};
// A member travels between MPI ranks as JSON (core/ensemble.hpp).
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ModulusMember, pressure, phi, modulus, modulus_linear, normal_stress_min,
                                   negative_modes, fire_iterations, force_max)

// The smallest normal stress min_a Sigma_aa of a periodic packing at x over its pressure Tr(Sigma)/D (eq.
// 9.26 in 2D, its analogue in 3D): about 1 for a packing jammed along every axis. The jamming protocols stop
// on the pressure alone, so a small packing can reach P_t with its contacts carrying the whole pressure
// along fewer axes (a column along z): then an unloaded axis has Sigma_aa ~ 0, and where no contact crosses
// the box boundary along y, U does not depend on the Lees-Edwards strain and G = 0.
double smallest_normal_stress(const DpmSystem& system, const Eigen::VectorXd& x);
double smallest_normal_stress(const DpmSystem3d& system, const Eigen::VectorXd& x);

// Called after each minimisation of the shear at each state: the state's index, then as ShearedSystemObserver.
template <class System>
using StateShearObserver = std::function<void(std::size_t state, int step, const System& system,
                                              const Eigen::VectorXd& x, double shear_stress)>;

// G at every state of a jamming run; a state has x, box, pressure and phi (JamState, Jam3dState);
// pressure_unit: the model's pressure unit in the system's stress unit; force_tolerance in the model's
// pressure unit (times length), as the scenes take it; storage: in 3D, the Hessian of the Newton steps;
// fire: the jamming protocol's FIRE settings, for the fallback where Newton falls short (shear_modulus.hpp).
template <class System, class States>
ModulusMember moduli_at_states(System system, const States& states, double pressure_unit, double dgamma,
                               int steps, double force_tolerance,
                               const StateShearObserver<System>& observe = {},
                               HessianStorage storage = HessianStorage::automatic,
                               const std::optional<FireOptions>& fire = {})
{
    ModulusMember m;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const auto& state = states[k];
        *system.box = state.box;
        ShearedSystemObserver<System> at_state;
        if (observe)
            at_state = [&observe, k](int step, const System& sheared, const Eigen::VectorXd& x,
                                     double stress) { observe(k, step, sheared, x, stress); };
        const double tolerance = force_tolerance * pressure_unit;
        ShearModulusResult g;
        if constexpr (std::is_same_v<System, DpmSystem3d>)
            g = shear_modulus(system, state.x, dgamma, steps, tolerance, at_state, storage, fire);
        else
            g = shear_modulus(system, state.x, dgamma, steps, tolerance, at_state, fire);
        m.pressure.push_back(state.pressure);
        m.phi.push_back(state.phi);
        m.modulus.push_back(g.modulus / pressure_unit);
        const LinearShearModulus linear = linear_shear_modulus(system, g.equilibrium);
        m.modulus_linear.push_back(linear.modulus / pressure_unit);
        m.normal_stress_min.push_back(smallest_normal_stress(system, g.equilibrium));
        m.negative_modes.push_back(linear.negative_modes);
        m.force_max = std::max(m.force_max, g.force_max);
    }
    return m;
}

// The ensemble's results; eta absent with fewer than two levels above onset with <G> > 0.
struct EnsembleModulus
{
    double G_onset = 0, G_max_pressure = 0;               // <G> at P_t and at the largest pressure
    double G_linear_onset = 0, G_linear_max_pressure = 0; // the same for the linear-response G
    int saddles = 0; // states (packing, pressure) whose Hessian has a negative mode
    // Slope of ln<G> against ln<P> and the standard error of that least-squares fit to the means (their
    // scatter about a line, not the ensemble's sampling error).
    std::optional<double> eta, eta_error;
    // The ensemble's standard error of eta, by the jackknife over the packings (shear_modulus_ensemble.cpp):
    // what a claim on eta is decided against.
    std::optional<double> eta_standard_error;
    // The same slope fitted to each packing's own G(P) above onset (where G > 0 at >= 2 pressures): their
    // sample standard deviation over the packings (>= 2 of them) and how many had a slope. The ensemble's
    // exponent is known to about spread / sqrt(packings) (the size a claim on eta needs).
    std::optional<double> eta_spread;
    int packings_with_slope = 0;
    long fire_iterations = 0;
    double force_max = 0;
};

// Names and units of the two tables: per packing (packing, P, phi, G, G_linear, negative_modes) and
// ensemble mean (P, G, G_linear).
struct ModulusTables
{
    std::string per_packing = "modulus.dat", mean = "mean_modulus.dat";
    std::string pressure_unit;    // e.g. "k_a a0"
    std::string pressure_meaning; // e.g. "pressure Tr(Sigma)/2, eq. (9.26)"
};

// Jackknife standard error of the exponent eta of the ensemble's <G>(<P>) over its n packings: with eta_(k)
// the exponent of the means without packing k, SE^2 = (n - 1)/n sum_k (eta_(k) - eta_(.))^2, eta_(.) their
// mean (Tukey's estimator; Efron and Stein, Ann. Statist. 9, 586 (1981)). eta is a non-linear function of
// ensemble means, so neither the fit's own error (the scatter of a few points about a line) nor the spread
// of the packings' own exponents (another estimator) is its sampling error; the jackknife's is. Absent below
// two packings and where leaving a packing out leaves fewer than two pressures above onset with <G> > 0.
std::optional<double> jackknife_exponent_error(const std::vector<ModulusMember>& members);

// Writes both tables and returns the means and the fit.
EnsembleModulus report_ensemble(const std::vector<ModulusMember>& members, const ModulusTables& tables,
                                RunContext& context);

// Summary keys G_onset, G_max_pressure, shear_modulus_exponent, shear_modulus_exponent_error,
// shear_modulus_exponent_standard_error (the jackknife's), shear_modulus_exponent_spread, force_max,
// G_linear_onset, G_linear_max_pressure and saddles, each followed by `suffix` (null for an absent
// exponent).
void write_modulus_summary(const EnsembleModulus& e, const std::string& suffix, nlohmann::json& summary);

} // namespace softgrain::dpm
