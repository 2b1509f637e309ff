#include "core/fire.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace softgrain {

FireResult fire_minimise(Eigen::VectorXd& x, const EnergyAndForce& energy_and_force,
                         const FireOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&start] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const double dofs = static_cast<double>(std::max<Eigen::Index>(1, x.size()));
    Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
    Eigen::VectorXd f(x.size());
    FireResult result;
    result.energy = energy_and_force(x, f);
    result.force_evaluations = 1;

    double dt = options.dt_initial;
    double alpha = options.alpha_start;
    int downhill_steps = 0;
    for (result.iterations = 0; result.iterations < options.max_iterations; ++result.iterations) {
        // |F|^2 and |v|^2 once per step, for the stopping rule and the mixing (norm() is their sqrt).
        const double force_squared = f.squaredNorm(), speed_squared = v.squaredNorm();
        result.force_rms = std::sqrt(force_squared / dofs);
        result.kinetic = 0.5 * speed_squared / dofs;
        if (result.force_rms < options.force_tolerance && result.kinetic < options.kinetic_tolerance) {
            result.converged = true;
            result.seconds = elapsed();
            return result;
        }
        if (options.hand_over && options.hand_over(result.iterations, result.force_rms)) {
            result.handed_over = true;
            result.seconds = elapsed();
            return result;
        }
        const double power = f.dot(v);
        if (power > 0) {
            const double force_norm = std::sqrt(force_squared);
            if (force_norm > 0) v = (1.0 - alpha) * v + alpha * std::sqrt(speed_squared) * f / force_norm;
            if (++downhill_steps > options.n_min) {
                dt = std::min(dt * options.f_inc, options.dt_max);
                alpha *= options.f_alpha;
            }
        } else {
            v.setZero();
            dt *= options.f_dec;
            alpha = options.alpha_start;
            downhill_steps = 0;
        }
        // Velocity Verlet with unit masses.
        v += 0.5 * dt * f;
        x += dt * v;
        result.energy = energy_and_force(x, f);
        ++result.force_evaluations;
        v += 0.5 * dt * f;
    }
    result.force_rms = std::sqrt(f.squaredNorm() / dofs);
    result.kinetic = 0.5 * v.squaredNorm() / dofs;
    result.seconds = elapsed();
    return result;
}

std::string fire_shortfall(const FireResult& result, const FireOptions& options)
{
    std::ostringstream out;
    out << std::setprecision(3) << "FIRE stopped after " << result.iterations << " iterations: force rms "
        << result.force_rms << " (tolerance " << options.force_tolerance << "), kinetic energy "
        << result.kinetic << " per degree of freedom (tolerance " << options.kinetic_tolerance << ")";
    return out.str();
}

} // namespace softgrain
