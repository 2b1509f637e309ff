#include "dpm/analysis/packing_hessian3d.hpp"

#include "dpm/analysis/sparse_modes.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace softgrain::dpm {

namespace {

// Lanczos vectors for lambda_max of a 3D packing: its top eigenvalues form a band (largest_eigenvalue).
constexpr Eigen::Index top_band_vectors = 80;

} // namespace

bool uses_sparse_hessian(HessianStorage storage, Eigen::Index degrees_of_freedom)
{
    if (storage == HessianStorage::automatic) return degrees_of_freedom > dense_hessian_limit3d;
    return storage == HessianStorage::sparse;
}

double polish_newton_sparse(const EnergyWithDerivatives& energy, const SparseHessianOf& hessian,
                            Eigen::VectorXd& x, double force_tolerance, int max_steps, double length)
{
    const double start_force = largest_force(energy, x);
    const double round_off = static_cast<double>(x.size()) * std::numeric_limits<double>::epsilon();
    Eigen::VectorXd best = x;
    double best_force = start_force;
    int factorizations = 0, without_progress = 0;
    for (int step = 0; step < max_steps && without_progress < 3; ++step) {
        Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
        energy(x, &g, nullptr);
        const double force = g.cwiseAbs().maxCoeff();
        if (force < best_force) {
            best = x;
            best_force = force;
            without_progress = 0;
        } else if (step > 0) {
            ++without_progress;
        }
        if (force < force_tolerance) break;
        const Eigen::SparseMatrix<double> m = hessian(x);
        const double bound = gershgorin_bound(m);
        double mu = std::max({g.norm() / length, pseudo_inverse_cut * bound, round_off * bound});
        const Eigen::VectorXd newton_step = regularised_newton_step(m, g, mu, bound, factorizations, step);
        const double fraction = damped_step_fraction(energy, x, newton_step, start_force);
        if (fraction == 0) break;
        x -= fraction * newton_step;
    }
    const double last_force = largest_force(energy, x);
    if (last_force < best_force) return last_force;
    x = best;
    return best_force;
}

bool leave_saddle_sparse(const EnergyWithDerivatives& energy, const SparseHessianOf& hessian,
                         Eigen::VectorXd& x, double force_unit, double eigenvalue_unit, double threshold,
                         double max_amplitude, double length)
{
    Eigen::VectorXd polished = x;
    polish_newton_sparse(energy, hessian, polished, 1e-14 * force_unit, 30, length);
    const Eigen::SparseMatrix<double> m = hessian(polished);
    const double largest = std::abs(largest_eigenvalue(m, top_band_vectors)) / eigenvalue_unit;
    const double bound = zero_mode_threshold(x.size(), largest, threshold);
    const std::optional<LowestModes> lowest = lowest_mode_below(m, bound * eigenvalue_unit);
    if (!lowest) return false;
    // The dense test's bound takes max|lambda| over the whole spectrum, lambda_0 included.
    const double lambda0 = lowest->spectrum.eigenvalues(0) / eigenvalue_unit;
    if (lambda0 > -zero_mode_threshold(x.size(), std::max(largest, std::abs(lambda0)), threshold))
        return false;
    return step_off_saddle(energy, polished, energy(polished, nullptr, nullptr),
                           lowest->spectrum.eigenvectors.col(0), max_amplitude, x);
}

EnergyWithDerivatives system_energy3d(const DpmSystem3d& system)
{
    return [&system](const Eigen::VectorXd& y, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian) {
        return total_energy3d(system, y, gradient, hessian);
    };
}

SparseHessianOf system_sparse_hessian3d(const DpmSystem3d& system)
{
    return [&system](const Eigen::VectorXd& y) { return sparse_dynamical_matrix3d(system, y); };
}

namespace {

double smallest_vertex_diameter(const DpmSystem3d& system)
{
    double sigma = std::numeric_limits<double>::infinity();
    for (const Particle3d& p : system.particles)
        sigma = std::min(sigma, p.sigma);
    return sigma;
}

} // namespace

double polish_newton3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_tolerance, int max_steps,
                       HessianStorage storage)
{
    if (!uses_sparse_hessian(storage, x.size()))
        return polish_newton(system_energy3d(system), x, force_tolerance, max_steps);
    return polish_newton_sparse(system_energy3d(system), system_sparse_hessian3d(system), x, force_tolerance,
                                max_steps, smallest_vertex_diameter(system));
}

double largest_eigenvalue3d(const DpmSystem3d& system, const Eigen::VectorXd& x, HessianStorage storage)
{
    if (uses_sparse_hessian(storage, x.size()))
        return largest_eigenvalue(sparse_dynamical_matrix3d(system, x), top_band_vectors);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(x.size(), x.size());
    total_energy3d(system, x, nullptr, &h);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

double polish_for_modes3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_unit,
                          HessianStorage storage)
{
    if (!uses_sparse_hessian(storage, x.size()))
        return polish_for_modes(system_energy3d(system), x, force_unit);
    return polish_newton_sparse(system_energy3d(system), system_sparse_hessian3d(system), x,
                                1e-14 * force_unit, 30, smallest_vertex_diameter(system));
}

bool leave_saddle3d(const DpmSystem3d& system, Eigen::VectorXd& x, double force_unit, double eigenvalue_unit,
                    double threshold, double max_amplitude, HessianStorage storage)
{
    if (!uses_sparse_hessian(storage, x.size()))
        return leave_saddle(system_energy3d(system), x, force_unit, eigenvalue_unit, threshold,
                            max_amplitude);
    return leave_saddle_sparse(system_energy3d(system), system_sparse_hessian3d(system), x, force_unit,
                               eigenvalue_unit, threshold, max_amplitude, smallest_vertex_diameter(system));
}

} // namespace softgrain::dpm
