#include "dpm/analysis/modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

namespace softgrain::dpm {

Eigen::MatrixXd dynamical_matrix(const DpmSystem& system, const Eigen::VectorXd& x)
{
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    total_energy(system, x, &g, &m);
    return m;
}

ModeSpectrum vibrational_modes(const DpmSystem& system, const Eigen::VectorXd& x)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dynamical_matrix(system, x));
    return {solver.eigenvalues(), solver.eigenvectors()};
}

int count_zero_modes(const Eigen::VectorXd& eigenvalues, double threshold)
{
    return static_cast<int>((eigenvalues.array().abs() < threshold).count());
}

int count_negative_modes(const Eigen::VectorXd& eigenvalues, double threshold)
{
    return static_cast<int>((eigenvalues.array() <= -threshold).count());
}

SpectrumCounts count_modes(const Eigen::VectorXd& eigenvalues, double threshold)
{
    return {count_negative_modes(eigenvalues, threshold), count_zero_modes(eigenvalues, threshold)};
}

double zero_mode_threshold(const Eigen::VectorXd& eigenvalues, double threshold)
{
    return zero_mode_threshold(eigenvalues.size(), eigenvalues.cwiseAbs().maxCoeff(), threshold);
}

double zero_mode_threshold(Eigen::Index n, double largest_magnitude, double threshold)
{
    const double round_off =
        static_cast<double>(n) * std::numeric_limits<double>::epsilon() * largest_magnitude;
    return std::max(threshold, round_off);
}

int free_particle_zero_modes(ShapeModel model, int vertices, int dimension)
{
    if (vertices == 1) return dimension;
    const int rigid_motions = dimension == 2 ? 3 : 6;
    if (model != ShapeModel::floppy) return rigid_motions;
    return dimension == 2 ? vertices - 1 : vertices + 3;
}

std::vector<bool> rattlers(const DpmSystem& system, const Eigen::VectorXd& x, double force_resolution)
{
    Eigen::VectorXd contact_forces = Eigen::VectorXd::Zero(x.size());
    total_energy(system, x, &contact_forces, nullptr, interaction_part);
    std::vector<bool> out;
    for (const Particle& q : system.particles) {
        const double largest = contact_forces.segment(2 * q.first, 2 * q.count).cwiseAbs().maxCoeff();
        out.push_back(largest <= q.count * force_resolution);
    }
    return out;
}

int zero_modes_beyond_rattlers(const DpmSystem& system, const Eigen::MatrixXd& zero_modes,
                               const std::vector<bool>& rattling)
{
    if (zero_modes.cols() == 0) return 0;
    Eigen::MatrixXd off_rattlers = zero_modes;
    for (std::size_t q = 0; q < system.particles.size(); ++q)
        if (rattling[q])
            off_rattlers.middleRows(2 * system.particles[q].first, 2 * system.particles[q].count).setZero();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(off_rattlers);
    return static_cast<int>((svd.singularValues().array() > 1e-4).count());
}

double largest_force(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x)
{
    Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
    energy(x, &f, nullptr);
    return f.cwiseAbs().maxCoeff();
}

double damped_step_fraction(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& step, double start_force)
{
    double fraction = 1;
    while (fraction > 1e-6 && !(largest_force(energy, x - fraction * step) < start_force))
        fraction /= 2;
    return fraction > 1e-6 ? fraction : 0;
}

double polish_newton(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_tolerance,
                     int max_steps)
{
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    const double start_force = largest_force(energy, x);
    for (int step = 0; step < max_steps; ++step) {
        g.setZero();
        Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
        energy(x, &g, &m);
        const double force = g.cwiseAbs().maxCoeff();
        if (force < force_tolerance) break;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(m);
        const Eigen::VectorXd& lambda = solver.eigenvalues();
        const double cut = pseudo_inverse_cut * lambda.cwiseAbs().maxCoeff();
        const Eigen::VectorXd projected = solver.eigenvectors().transpose() * g;
        Eigen::VectorXd step_in_modes = Eigen::VectorXd::Zero(x.size());
        for (Eigen::Index k = 0; k < lambda.size(); ++k)
            if (lambda(k) > cut) step_in_modes(k) = projected(k) / lambda(k);
        // A full step to a force above the FIRE-relaxed start has left the quadratic basin (a contact
        // opened or closed, or a soft mode with lambda just above the cut): halve it until the force is
        // below the start's again; stop where 20 halvings do not help. Rises below the start's force are
        // accepted: on a manifold of minima (floppy packings) the largest force can rise for a step before
        // it falls quadratically.
        const Eigen::VectorXd newton_step = solver.eigenvectors() * step_in_modes;
        const double fraction = damped_step_fraction(energy, x, newton_step, start_force);
        if (fraction == 0) break;
        x -= fraction * newton_step;
    }
    return largest_force(energy, x);
}

EnergyWithDerivatives system_energy(const DpmSystem& system)
{
    return [&system](const Eigen::VectorXd& y, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian) {
        return total_energy(system, y, gradient, hessian);
    };
}

double polish_newton(const DpmSystem& system, Eigen::VectorXd& x, double force_tolerance, int max_steps)
{
    return polish_newton(system_energy(system), x, force_tolerance, max_steps);
}

double polish_for_modes(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_unit)
{
    return polish_newton(energy, x, 1e-14 * force_unit, 30);
}

double polish_for_modes(const DpmSystem& system, Eigen::VectorXd& x, double force_unit)
{
    return polish_newton(system, x, 1e-14 * force_unit, 30);
}

bool leave_saddle(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_unit,
                  double eigenvalue_unit, double threshold, double max_amplitude)
{
    Eigen::VectorXd polished = x;
    polish_for_modes(energy, polished, force_unit);
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
    const double u0 = energy(polished, nullptr, &m);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(m);
    const Eigen::VectorXd lambda = solver.eigenvalues() / eigenvalue_unit;
    if (lambda(0) > -zero_mode_threshold(lambda, threshold)) return false;
    return step_off_saddle(energy, polished, u0, solver.eigenvectors().col(0), max_amplitude, x);
}

bool step_off_saddle(const EnergyWithDerivatives& energy, const Eigen::VectorXd& polished, double u0,
                     const Eigen::VectorXd& lowest, double max_amplitude, Eigen::VectorXd& x)
{
    const double round_off =
        static_cast<double>(x.size()) * std::numeric_limits<double>::epsilon() * std::abs(u0);
    double best_change = -round_off, best_amplitude = 0;
    for (double a = 1e-6; a <= max_amplitude; a *= 2)
        for (double signed_a : {a, -a}) {
            const double change = energy_change_along(energy, polished, lowest, signed_a);
            if (change < best_change) {
                best_change = change;
                best_amplitude = signed_a;
            }
        }
    if (best_amplitude == 0) return false;
    x = polished + best_amplitude * lowest;
    return true;
}

double energy_change_along(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& mode, double amplitude)
{
    const Eigen::VectorXd moved = x + amplitude * mode;
    return energy(moved, nullptr, nullptr) - energy(x, nullptr, nullptr);
}

double energy_change_along(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode,
                           double amplitude)
{
    return energy_change_along(system_energy(system), x, mode, amplitude);
}

double local_exponent(double du1, double du2, double dr1, double dr2, double floor)
{
    if (!(du1 > floor && du2 > floor)) return std::nan("");
    return std::log(du2 / du1) / std::log(dr2 / dr1);
}

std::optional<double> median_exponent(std::vector<double> exponents)
{
    std::erase_if(exponents, [](double exponent) { return std::isnan(exponent); });
    if (exponents.empty()) return std::nullopt;
    std::sort(exponents.begin(), exponents.end());
    return exponents[exponents.size() / 2];
}

double participation_ratio(const Eigen::VectorXd& mode)
{
    const Eigen::Index N = mode.size() / 2;
    double s2 = 0, s4 = 0;
    for (Eigen::Index i = 0; i < N; ++i) {
        const double u2 = mode.segment<2>(2 * i).squaredNorm();
        s2 += u2;
        s4 += u2 * u2;
    }
    return s2 * s2 / (static_cast<double>(N) * s4);
}

namespace {

// One particle's vertices r and mode field u (Dim x n) split into u_i = t + omega x (r_i - c) + d_i: t the
// mean of u_i, omega the least-squares rigid rotation about the vertex mean c (I omega = sum (r_i - c) x u_i
// with the inertia I = sum |r_i - c|^2 1 - (r_i - c)(r_i - c)^T in 3D; in 2D omega is a scalar and I the sum
// of |r_i - c|^2). The unnormalised parts |t|^2 n, |omega x (r - c)|^2 and |d|^2 are added to `parts`.
// A one-vertex particle has I = 0 and no rotation part.
template <int Dim>
void add_particle_mode_parts(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& r,
                             const Eigen::Matrix<double, Dim, Eigen::Dynamic>& u, ModeParts& parts)
{
    const Eigen::Matrix<double, Dim, 1> c = r.rowwise().mean(), t = u.rowwise().mean();
    const Eigen::Matrix<double, Dim, Eigen::Dynamic> arm = r.colwise() - c;
    Eigen::Matrix<double, Dim, Eigen::Dynamic> rotation(Dim, r.cols());
    if constexpr (Dim == 2) {
        const double inertia = arm.squaredNorm();
        double omega = 0;
        for (Eigen::Index i = 0; i < r.cols(); ++i)
            omega += arm(0, i) * u(1, i) - arm(1, i) * u(0, i);
        if (inertia > 0) omega /= inertia;
        rotation.row(0) = -omega * arm.row(1);
        rotation.row(1) = omega * arm.row(0);
    } else {
        Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
        Eigen::Vector3d moment = Eigen::Vector3d::Zero();
        for (Eigen::Index i = 0; i < r.cols(); ++i) {
            const Eigen::Vector3d a = arm.col(i);
            inertia += a.squaredNorm() * Eigen::Matrix3d::Identity() - a * a.transpose();
            moment += a.cross(Eigen::Vector3d(u.col(i)));
        }
        // Minimum-norm least squares: a singular I (one vertex, or all on a line) leaves no rotation
        // about the axis it cannot resolve.
        const Eigen::Vector3d omega = inertia.completeOrthogonalDecomposition().solve(moment);
        for (Eigen::Index i = 0; i < r.cols(); ++i)
            rotation.col(i) = omega.cross(Eigen::Vector3d(arm.col(i)));
    }
    parts.translation += static_cast<double>(r.cols()) * t.squaredNorm();
    parts.rotation += rotation.squaredNorm();
    parts.deformation += ((u.colwise() - t) - rotation).squaredNorm();
}

// The same for particle p (a block of `count` vertices from `first`) of a mode over the whole system.
template <int Dim, class Particle>
void add_mode_parts_on(const Particle& p, const Eigen::VectorXd& x, const Eigen::VectorXd& mode,
                       ModeParts& parts)
{
    add_particle_mode_parts<Dim>(x.segment(Dim * p.first, Dim * p.count).reshaped(Dim, p.count),
                                 mode.segment(Dim * p.first, Dim * p.count).reshaped(Dim, p.count), parts);
}

// Shares of |u|^2: the three parts divided by their sum (which is |u|^2, the parts being orthogonal).
ModeParts normalised(ModeParts parts)
{
    const double total = parts.translation + parts.rotation + parts.deformation;
    if (total > 0) {
        parts.translation /= total;
        parts.rotation /= total;
        parts.deformation /= total;
    }
    return parts;
}

// The parts of a mode summed over the particles (each a block of `count` vertices from `first`), normalised.
template <int Dim, class Particles>
ModeParts decompose_mode_of(const Particles& particles, const Eigen::VectorXd& x, const Eigen::VectorXd& mode)
{
    ModeParts parts;
    for (const auto& p : particles)
        add_mode_parts_on<Dim>(p, x, mode, parts);
    return normalised(parts);
}

// The zero-mode subspace orthogonal to the uniform translations, as an orthonormal basis (columns).
template <int Dim>
Eigen::MatrixXd nontrivial_zero_mode_basis(const Eigen::MatrixXd& zero_modes)
{
    const Eigen::Index n = zero_modes.rows();
    Eigen::MatrixXd translations = Eigen::MatrixXd::Zero(n, Dim);
    for (Eigen::Index i = 0; i < n; ++i)
        translations(i, i % Dim) = 1.0 / std::sqrt(static_cast<double>(n / Dim));
    const Eigen::MatrixXd rest = zero_modes - translations * (translations.transpose() * zero_modes);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rest, Eigen::ComputeThinU);
    const auto kept = (svd.singularValues().array() > 0.5).count();
    return svd.matrixU().leftCols(kept);
}

template <int Dim, class Particles>
std::vector<ModeParts> nontrivial_zero_mode_parts_of(const Particles& particles, const Eigen::VectorXd& x,
                                                     const Eigen::MatrixXd& zero_modes, int& dimension_out)
{
    const Eigen::MatrixXd basis = nontrivial_zero_mode_basis<Dim>(zero_modes);
    dimension_out = static_cast<int>(basis.cols());
    std::vector<ModeParts> parts(particles.size());
    for (std::size_t m = 0; m < particles.size(); ++m) {
        for (Eigen::Index k = 0; k < basis.cols(); ++k)
            add_mode_parts_on<Dim>(particles[m], x, basis.col(k), parts[m]);
        if (dimension_out > 0) {
            parts[m].translation /= dimension_out;
            parts[m].rotation /= dimension_out;
            parts[m].deformation /= dimension_out;
        }
    }
    return parts;
}

} // namespace

std::vector<ModeParts> nontrivial_zero_mode_parts(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                                  const Eigen::MatrixXd& zero_modes, int& dimension_out)
{
    return nontrivial_zero_mode_parts_of<3>(system.particles, x, zero_modes, dimension_out);
}

ModeParts decompose_mode(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode)
{
    return decompose_mode_of<2>(system.particles, x, mode);
}

ModeParts decompose_mode(const DpmSystem3d& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode)
{
    return decompose_mode_of<3>(system.particles, x, mode);
}

} // namespace softgrain::dpm
