#include "vsm/stability.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"

#include <cmath>
#include <sstream>

namespace softgrain::vsm {

double effective_wave_speed(const Material& material, const ModelOptions& options)
{
    const LameParameters m = material.lame();
    return std::sqrt((m.lambda + 2 * m.mu + options.xi_n * material.young) / material.density);
}

double predicted_time_step_limit(const Model& model)
{
    return stable_cfl_factor * model.min_branch_length() /
           effective_wave_speed(model.material(), model.options());
}

void check_time_step(const Model& model, double dt)
{
    const double limit = predicted_time_step_limit(model);
    if (dt <= limit) return;
    std::ostringstream m;
    m << "time step dt = " << dt << " s above the stability limit " << limit << " s = " << stable_cfl_factor
      << " L_min / c_eff (L_min = " << model.min_branch_length()
      << " m, c_eff = sqrt((lambda + 2 mu + xi_n E)/rho) = "
      << effective_wave_speed(model.material(), model.options()) << " m/s)";
    throw NumericalError(m.str(), 0, "cfl too large: reduce it below the limit (refused before the run)");
}

double highest_frequency(const Model& model, const Points<3>& x, double t, int iterations)
{
    const auto n = static_cast<Eigen::Index>(model.size());
    Eigen::VectorXd mass(3 * n);
    for (Eigen::Index a = 0; a < n; ++a)
        mass.segment<3>(3 * a).setConstant(model.mass()[static_cast<std::size_t>(a)]);
    // K v by central differences, step relative to the particle spacing (forces are smooth in x).
    const double epsilon = 1e-7 * model.min_branch_length();
    const auto stiffness_times = [&](const Eigen::VectorXd& v) {
        const Points<3> dv =
            Eigen::Map<const Points<3>>(v.data(), 3, n) * (epsilon / v.cwiseAbs().maxCoeff());
        const Points<3> df = model.forces(x + dv, t) - model.forces(x - dv, t);
        return Eigen::VectorXd(-Eigen::Map<const Eigen::VectorXd>(df.data(), 3 * n) *
                               (v.cwiseAbs().maxCoeff() / (2 * epsilon)));
    };
    Rng rng(12345);
    Eigen::VectorXd v(3 * n);
    for (Eigen::Index i = 0; i < v.size(); ++i)
        v[i] = rng.uniform(-1.0, 1.0);
    double omega2 = 0;
    for (int k = 0; k < iterations; ++k) {
        const Eigen::VectorXd Kv = stiffness_times(v);
        omega2 = v.dot(Kv) / v.dot(mass.cwiseProduct(v)); // Rayleigh quotient
        v = Kv.cwiseQuotient(mass);
        v /= std::sqrt(v.dot(mass.cwiseProduct(v)));
    }
    return std::sqrt(omega2);
}

} // namespace softgrain::vsm
