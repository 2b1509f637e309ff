#include "dpm/relax/newton_relax.hpp"

#include "core/errors.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/sparse_modes.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace softgrain::dpm {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// Translations sampled by energy_round_off.
constexpr int round_off_samples = 8;

double seconds_from(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double rms(const Eigen::VectorXd& force)
{
    return std::sqrt(force.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, force.size())));
}

// The dimension of a relaxation: the system's energy, Hessian and touching pairs, and its translations.
double total_energy_of(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient)
{
    return total_energy(system, x, gradient, nullptr);
}

double total_energy_of(const DpmSystem3d& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient)
{
    return total_energy3d(system, x, gradient, nullptr);
}

Eigen::SparseMatrix<double> hessian_of(const DpmSystem& system, const Eigen::VectorXd& x)
{
    return sparse_dynamical_matrix(system, x);
}

Eigen::SparseMatrix<double> hessian_of(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    return sparse_dynamical_matrix3d(system, x);
}

// The touching pairs at x: what a step may change outside the Hessian's model.
std::vector<std::pair<int, int>> touching_pairs(const DpmSystem& system, const Eigen::VectorXd& x)
{
    std::vector<std::pair<int, int>> pairs;
    if (system.interaction == InteractionKind::none) return pairs;
    for (const VertexContact& c : vertex_contacts(system, x))
        pairs.emplace_back(c.i, c.j);
    return pairs;
}

std::vector<std::pair<int, int>> touching_pairs(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    return touching_pairs3d(system, x);
}

template <RelaxableSystem System>
constexpr int dimension_of = std::same_as<System, DpmSystem> ? 2 : 3;

// The system with its anchors moved by `shift` (2D; a 3D system has none).
DpmSystem with_anchors_moved(const DpmSystem& system, const Eigen::Vector2d& shift)
{
    DpmSystem moved = system;
    for (Anchor& a : moved.anchors)
        a.position += shift;
    return moved;
}

const DpmSystem3d& with_anchors_moved(const DpmSystem3d& system, const Eigen::Vector3d&)
{
    return system;
}

// U and F = -grad U at x.
template <RelaxableSystem System>
double energy_and_force(const System& system, const Eigen::VectorXd& x, Eigen::VectorXd& force)
{
    force.setZero(x.size());
    const double energy = total_energy_of(system, x, &force);
    force = -force;
    return energy;
}

template <RelaxableSystem System>
double smallest_vertex_diameter(const System& system)
{
    double sigma = std::numeric_limits<double>::infinity();
    for (const auto& p : system.particles)
        sigma = std::min(sigma, p.sigma);
    return sigma;
}

void require_finite(double energy, const Eigen::VectorXd& force, int step, const std::string& where)
{
    if (!std::isfinite(energy) || !force.allFinite())
        throw NumericalError(
            "energy " + number_text(energy) + " and forces of the Newton finisher at " + where, step,
            "non-finite coordinates, or a degenerate particle (an edge of zero length)");
}

} // namespace

Relaxation relaxation_from_name(const std::string& name)
{
    if (name == "fire") return Relaxation::fire;
    if (name == "fire_newton") return Relaxation::fire_newton;
    throw InputError("relaxation = '" + name + "': allowed fire | fire_newton");
}

Eigen::VectorXd regularised_newton_step(const Eigen::SparseMatrix<double>& hessian,
                                        const Eigen::VectorXd& force, double& mu, double bound,
                                        int& factorizations, int step_index)
{
    Eigen::SparseMatrix<double> identity(hessian.rows(), hessian.cols());
    identity.setIdentity();
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
    ldlt.analyzePattern(hessian + identity); // the pattern of M + mu I for any mu
    for (;;) {
        ldlt.factorize(hessian + mu * identity);
        ++factorizations;
        if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0) break;
        if (mu >= 2 * bound)
            throw NumericalError(
                "LDL^T factor of M + mu I at mu = " + number_text(mu) + " = 2 max row sum of |M|", step_index,
                "a pivot <= 0 where M + mu I is definite by Gershgorin: M has a non-finite entry "
                "or the factor is ruined by round-off");
        mu = std::min(10 * mu, 2 * bound);
    }
    Eigen::VectorXd step = ldlt.solve(force);
    if (!step.allFinite())
        throw NumericalError("Newton step solving (M + mu I) dx = F at mu = " + number_text(mu), step_index,
                             "a non-finite force or an ill-conditioned factor");
    return step;
}

template <RelaxableSystem System>
FireResult relax_fire(const System& system, Eigen::VectorXd& x, const FireOptions& options)
{
    return fire_minimise(
        x, [&system](const Eigen::VectorXd& y, Eigen::VectorXd& f) { return energy_and_force(system, y, f); },
        options);
}

template <RelaxableSystem System>
double energy_round_off(const System& system, const Eigen::VectorXd& x, double energy)
{
    constexpr int D = dimension_of<System>;
    using Shift = Eigen::Matrix<double, D, 1>;
    const double sigma = smallest_vertex_diameter(system);
    // Translations by the fractional parts of k (sqrt 2, sqrt 3, sqrt 5) sigma (an additive recurrence of
    // irrational steps), so that no coordinate moves by a round number and no two shifts repeat.
    const Eigen::Vector3d step(std::numbers::sqrt2, std::numbers::sqrt3, std::sqrt(5.0));
    double squares = 0;
    for (int k = 1; k <= round_off_samples; ++k) {
        const Eigen::Vector3d fraction = (k * step).unaryExpr([](double v) { return v - std::floor(v); });
        const Shift shift = fraction.head<D>() * sigma;
        Eigen::VectorXd y = x;
        y.reshaped(D, x.size() / D).colwise() += shift;
        const double change = total_energy_of(with_anchors_moved(system, shift), y, nullptr) - energy;
        squares += change * change;
    }
    return 6 * std::sqrt(squares / round_off_samples) + 16 * eps * std::abs(energy);
}

template <RelaxableSystem System>
NewtonResult newton_finish(const System& system, Eigen::VectorXd& x, const NewtonOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    NewtonResult result;
    Eigen::VectorXd force(x.size()), trial_force(x.size());
    double energy = energy_and_force(system, x, force);
    ++result.force_evaluations;
    require_finite(energy, force, 0, "the start");
    std::vector<std::pair<int, int>> touching = touching_pairs(system, x); // at x, kept with it
    const double noise = energy_round_off(system, x, energy);
    const double length = smallest_vertex_diameter(system);
    result.energies.push_back(energy);
    result.force_norms.push_back(force.norm());
    double theta = 1; // mu = theta |F| / sigma, theta >= 1
    int rejections_in_row = 0, slow_steps = 0;
    double force_at_last_halving = force.norm();
    const auto finish = [&](bool converged, std::string reason) {
        result.converged = converged;
        result.stop_reason = std::move(reason);
        result.energy = energy;
        result.force_rms = rms(force);
        result.seconds = seconds_from(start);
        return result;
    };
    Eigen::SparseMatrix<double> hessian;
    bool hessian_current = false;
    double bound = 0;
    for (int factorised = 0;;) {
        if (rms(force) < options.force_tolerance) return finish(true, "");
        if (factorised >= options.max_steps) return finish(false, "no convergence in the step budget");
        if (!hessian_current) {
            hessian = hessian_of(system, x);
            ++result.force_evaluations;
            bound = gershgorin_bound(hessian);
            if (!std::isfinite(bound))
                throw NumericalError("dynamical matrix of the Newton finisher", result.steps,
                                     "a non-finite second derivative (a degenerate particle)");
            hessian_current = true;
        }
        // Never below the round-off bound of M's zero eigenvalues (n eps R), which may come out negative.
        const double shift =
            std::max(theta * force.norm() / length, static_cast<double>(x.size()) * eps * bound);
        double mu = shift;
        const int factors_before = result.factorizations;
        const Eigen::VectorXd step =
            regularised_newton_step(hessian, force, mu, bound, result.factorizations, result.steps);
        factorised += result.factorizations - factors_before;
        // A curvature of M below -100 times the shift: x is on the way over a saddle (a rearrangement), far
        // from the quadratic basin of a minimum, where FIRE's damped dynamics does better.
        if (mu > 100 * shift)
            return finish(false, "negative curvature " + number_text(-mu) + " beyond the shift " +
                                     number_text(shift) + ": not near a minimum");
        theta = std::max(theta, mu * length / force.norm());
        const double predicted = force.dot(step) - 0.5 * step.dot(hessian * step);
        const Eigen::VectorXd trial = x + step;
        const double trial_energy = energy_and_force(system, trial, trial_force);
        ++result.force_evaluations;
        require_finite(trial_energy, trial_force, result.steps, "a trial point");
        const double decrease = energy - trial_energy;
        const bool at_round_off = std::abs(decrease) <= noise;
        const bool accepted = at_round_off ? trial_force.norm() < force.norm() : decrease > 0;
        if (!accepted) {
            ++result.rejections;
            // The model's curvature along the rejected step is dx.(M + mu) dx / |dx|^2 = F.dx / |dx|^2 >= mu;
            // a shift of 4 times it shortens the step about 4-fold (theta *= 4 alone barely does while
            // mu is far below M's eigenvalues along dx).
            theta = 4 * std::max(mu, force.dot(step) / step.squaredNorm()) * length / force.norm();
            if (++rejections_in_row >= options.max_rejections)
                return finish(false, std::to_string(rejections_in_row) +
                                         " rejected steps in a row (the energy rose or stayed at round-off)");
            continue;
        }
        rejections_in_row = 0;
        const double ratio = decrease / predicted;
        if (!at_round_off && ratio < 0.25) theta *= 4;
        if (at_round_off || ratio > 0.75) theta = std::max(1.0, theta / 4);
        std::vector<std::pair<int, int>> trial_touching = touching_pairs(system, trial);
        result.contact_changes += trial_touching != touching ? 1 : 0;
        touching.swap(trial_touching);
        x = trial;
        energy = trial_energy;
        force.swap(trial_force);
        hessian_current = false;
        ++result.steps;
        result.energies.push_back(energy);
        result.force_norms.push_back(force.norm());
        if (force.norm() < 0.5 * force_at_last_halving) {
            force_at_last_halving = force.norm();
            slow_steps = 0;
        } else if (++slow_steps >= options.max_slow_steps) {
            return finish(false, std::to_string(slow_steps) + " accepted steps without halving the force");
        }
    }
}

template <RelaxableSystem System>
RelaxResult relax(const System& system, Eigen::VectorXd& x, const RelaxOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    RelaxResult result;
    const double tolerance = options.fire.force_tolerance;
    const bool newton = options.method == Relaxation::fire_newton;
    for (;;) {
        FireOptions fire = options.fire;
        fire.max_iterations = options.fire.max_iterations - result.fire_iterations;
        // Crawl detection: the lowest force rms of this FIRE run and the iteration it last halved at.
        double lowest = std::numeric_limits<double>::infinity(), lowest_at_halving = lowest;
        long halved_at = 0;
        if (newton && result.handovers < options.max_handovers)
            fire.hand_over = [&](long iteration, double force_rms) {
                if (!std::isfinite(force_rms)) return true; // the finisher diagnoses it (NumericalError)
                lowest = std::min(lowest, force_rms);
                if (lowest < 0.5 * lowest_at_halving) {
                    lowest_at_halving = lowest;
                    halved_at = iteration;
                }
                const bool crawling = iteration - halved_at > options.crawl_window;
                // After an unconverged finisher FIRE first runs a crawl window of its own: the finisher's
                // state is no better suited to it than the one it was given.
                if (result.handovers > 0 && iteration < options.crawl_window) return false;
                return force_rms < options.handover_factor * tolerance ||
                       (crawling && force_rms < options.crawl_factor * tolerance);
            };
        result.last_fire = relax_fire(system, x, fire);
        result.fire_iterations += result.last_fire.iterations;
        result.force_evaluations += result.last_fire.force_evaluations;
        result.fire_seconds += result.last_fire.seconds;
        result.energy = result.last_fire.energy;
        result.force_rms = result.last_fire.force_rms;
        result.kinetic = result.last_fire.kinetic;
        if (!result.last_fire.handed_over) {
            result.converged = result.last_fire.converged;
            break;
        }
        ++result.handovers;
        NewtonOptions finisher;
        finisher.force_tolerance = tolerance;
        const NewtonResult n = newton_finish(system, x, finisher);
        result.newton_steps += n.steps;
        result.factorizations += n.factorizations;
        result.newton_seconds += n.seconds;
        result.energy = n.energy;
        result.force_rms = n.force_rms;
        result.kinetic = 0; // the finisher's state is at rest
        if (n.converged) {
            result.converged = true;
            break;
        }
        result.newton_stop_reason = n.stop_reason;
    }
    result.seconds = seconds_from(start);
    return result;
}

template FireResult relax_fire(const DpmSystem&, Eigen::VectorXd&, const FireOptions&);
template FireResult relax_fire(const DpmSystem3d&, Eigen::VectorXd&, const FireOptions&);
template double energy_round_off(const DpmSystem&, const Eigen::VectorXd&, double);
template double energy_round_off(const DpmSystem3d&, const Eigen::VectorXd&, double);
template NewtonResult newton_finish(const DpmSystem&, Eigen::VectorXd&, const NewtonOptions&);
template NewtonResult newton_finish(const DpmSystem3d&, Eigen::VectorXd&, const NewtonOptions&);
template RelaxResult relax(const DpmSystem&, Eigen::VectorXd&, const RelaxOptions&);
template RelaxResult relax(const DpmSystem3d&, Eigen::VectorXd&, const RelaxOptions&);

std::string relax_shortfall(const RelaxResult& result, const RelaxOptions& options)
{
    std::string text = fire_shortfall(result.last_fire, options.fire);
    if (result.handovers > 0)
        text += "; after " + std::to_string(result.handovers) + " Newton hand-overs (" +
                std::to_string(result.newton_steps) + " steps, last stop: " + result.newton_stop_reason + ")";
    return text;
}

} // namespace softgrain::dpm
