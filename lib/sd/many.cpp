#include "sd/many.hpp"

#include "core/errors.hpp"
#include "core/gsl_checked.hpp"
#include "sd/pair_dynamics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <memory>
#include <numbers>

namespace softgrain::sd {

ManyParticleRates many_particle_rates(const ManyParticleSystem& s, double t,
                                      const std::vector<double>& positions, const std::vector<double>& gaps)
{
    const int d = s.dimension;
    const int n = static_cast<int>(positions.size()) / d;
    const int rows = d * n;
    std::vector<double> force(rows), force_rate(rows);
    s.external(t, force, force_rate);

    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(rows, rows);
    Eigen::VectorXd b = -Eigen::Map<const Eigen::VectorXd>(force_rate.data(), rows);
    ManyParticleRates out;
    out.gap_rate.resize(s.bonds.size());
    out.pair_force.resize(s.bonds.size());
    out.deflection.resize(s.bonds.size());
    for (std::size_t k = 0; k < s.bonds.size(); ++k) {
        const auto [i, j] = s.bonds[k];
        Eigen::VectorXd separation(d);
        for (int c = 0; c < d; ++c)
            separation[c] = positions[j * d + c] - positions[i * d + c];
        const double distance = separation.norm();
        const Eigen::VectorXd normal = separation / distance;
        // The pair's own quantities at (|X_ij|, h_ij); the forces passed here are not used.
        const PairRates r = soft_dynamics_rates(s.laws, s.material.radius, distance, gaps[k], 0.0, 0.0);
        out.pair_force[k] = r.F_ela;
        out.deflection[k] = r.delta;
        out.gap_rate[k] = -(r.F_ela - r.F_adh) / r.zeta; // eq. (7) for pair ij
        const Eigen::MatrixXd block = r.C * normal * normal.transpose();
        L.block(i * d, j * d, d, d) += block;
        L.block(i * d, i * d, d, d) -= block;
        L.block(j * d, i * d, d, d) += block;
        L.block(j * d, j * d, d, d) -= block;
        const Eigen::VectorXd relaxation = (r.C / r.D) * (r.F_ela - r.F_adh) * normal;
        b.segment(i * d, d) -= relaxation; // n_ij points from i to j
        b.segment(j * d, d) += relaxation; // n_ji = -n_ij
    }
    // Replace particle 0's rows by zero mean velocity; in 2D add zero mean rotation about the centroid.
    const int extra = d == 2 ? 1 : 0;
    Eigen::MatrixXd A(rows + extra, rows);
    Eigen::VectorXd rhs(rows + extra);
    A.topRows(rows) = L;
    rhs.head(rows) = b;
    for (int c = 0; c < d; ++c) {
        A.row(c).setZero();
        for (int i = 0; i < n; ++i)
            A(c, i * d + c) = 1.0;
        rhs[c] = 0;
    }
    if (d == 2) {
        double cx = 0, cy = 0;
        for (int i = 0; i < n; ++i)
            cx += positions[2 * i] / n, cy += positions[2 * i + 1] / n;
        A.row(rows).setZero();
        for (int i = 0; i < n; ++i) {
            A(rows, 2 * i) = -(positions[2 * i + 1] - cy);
            A(rows, 2 * i + 1) = positions[2 * i] - cx;
        }
        rhs[rows] = 0;
    }
    const Eigen::VectorXd velocity = A.completeOrthogonalDecomposition().solve(rhs);
    out.velocity.assign(velocity.data(), velocity.data() + rows);
    // The replaced rows must still hold: the full system is consistent only if the external forces balance.
    const double scale = L.cwiseAbs().maxCoeff() * velocity.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
    out.residual = scale > 0 ? (L * velocity - b).cwiseAbs().maxCoeff() / scale : 0.0;
    return out;
}

namespace {

struct ManyOde
{
    const ManyParticleSystem* system;
    std::size_t coordinates;
};

int many_rhs(double t, const double y[], double f[], void* params)
{
    const auto* p = static_cast<const ManyOde*>(params);
    const std::size_t bonds = p->system->bonds.size();
    std::vector<double> positions(y, y + p->coordinates),
        gaps(y + p->coordinates, y + p->coordinates + bonds);
    if (std::any_of(gaps.begin(), gaps.end(), [](double h) { return !(h > 0); })) return GSL_FAILURE;
    const ManyParticleRates r = many_particle_rates(*p->system, t, positions, gaps);
    std::copy(r.velocity.begin(), r.velocity.end(), f);
    std::copy(r.gap_rate.begin(), r.gap_rate.end(), f + p->coordinates);
    for (std::size_t i = 0; i < p->coordinates + bonds; ++i)
        if (!std::isfinite(f[i])) return GSL_FAILURE;
    return GSL_SUCCESS;
}

} // namespace

std::vector<ManySample> integrate_many(const ManyParticleSystem& system, std::vector<double> positions,
                                       std::vector<double> gaps, const std::vector<double>& output_times,
                                       double h_min, double tolerance, double delta_scale, long& steps)
{
    ManyOde ode{&system, positions.size()};
    const std::size_t dim = positions.size() + gaps.size();
    gsl_odeiv2_system sys{many_rhs, nullptr, dim, &ode};
    std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
        checked_gsl_allocation(
            gsl_odeiv2_driver_alloc_standard_new(&sys, gsl_odeiv2_step_rk8pd, output_times.front() * 1e-3,
                                                 tolerance * delta_scale, tolerance, 1.0, 0.0),
            "the many-particle ODE (rk8pd)"),
        gsl_odeiv2_driver_free);
    std::vector<double> y(positions);
    y.insert(y.end(), gaps.begin(), gaps.end());
    double t = 0;
    std::vector<ManySample> samples;
    const auto record = [&] {
        std::vector<double> x(y.begin(), y.begin() + positions.size()),
            h(y.begin() + positions.size(), y.end());
        samples.push_back({t, x, h, many_particle_rates(system, t, x, h)});
    };
    record();
    steps = 0;
    for (double target : output_times) {
        const int status = gsl_odeiv2_driver_apply(driver.get(), &t, target, y.data());
        steps += static_cast<long>(driver->n); // the driver counts the steps of each call from zero
        if (status != GSL_SUCCESS)
            throw NumericalError("many-particle integration (rk8pd): " + std::string(gsl_strerror(status)),
                                 static_cast<std::int64_t>(driver->n),
                                 "a gap reached zero or the step underflowed");
        record();
        if (*std::min_element(y.begin() + positions.size(), y.end()) <= h_min) break;
    }
    return samples;
}

BalancedStart compressed_line(const Material& material, int particles, double force, double h0)
{
    BalancedStart start{{material, paper_contact_laws(material), 1, {}, {}}, {}, force, 0, 0};
    start.deflection = balanced_deflection(start.system.laws, h0, force);
    start.distance = 2.0 * material.radius + h0 - 2.0 * start.deflection; // eq. (2)
    const long long n = particles;
    for (long long i = 0; i < n; ++i)
        start.positions.push_back(static_cast<double>(i) * start.distance);
    for (long long i = 0; i + 1 < n; ++i)
        start.system.bonds.push_back({static_cast<int>(i), static_cast<int>(i + 1)});
    start.system.external = [n, force](double, std::vector<double>& external, std::vector<double>& rate) {
        std::fill(external.begin(), external.end(), 0.0);
        std::fill(rate.begin(), rate.end(), 0.0);
        external.front() = force;
        external[n - 1] = -force;
    };
    return start;
}

BalancedStart pushed_triangle(const Material& material, double force, double h0)
{
    BalancedStart start{
        {material, paper_contact_laws(material), 2, {}, {}}, {}, force / std::sqrt(3.0), 0, 0};
    start.deflection = balanced_deflection(start.system.laws, h0, start.pair_force);
    start.distance = 2.0 * material.radius + h0 - 2.0 * start.deflection; // eq. (2)
    const double radius = start.distance / std::sqrt(3.0);
    for (int i = 0; i < 3; ++i) {
        const double angle = std::numbers::pi / 2 + 2.0 * std::numbers::pi * i / 3.0;
        start.positions.push_back(radius * std::cos(angle));
        start.positions.push_back(radius * std::sin(angle));
    }
    start.system.bonds = {{0, 1}, {1, 2}, {2, 0}};
    start.system.external = [force, initial = start.positions](double, std::vector<double>& external,
                                                               std::vector<double>& rate) {
        for (int i = 0; i < 3; ++i) { // toward the centre of the triangle (fixed direction)
            const double norm = std::hypot(initial[2 * i], initial[2 * i + 1]);
            external[2 * i] = -force * initial[2 * i] / norm;
            external[2 * i + 1] = -force * initial[2 * i + 1] / norm;
        }
        std::fill(rate.begin(), rate.end(), 0.0);
    };
    return start;
}

ManyMaxima many_maxima(const std::vector<ManySample>& samples, int dimension, const ApproachProblem& pair,
                       double pair_force)
{
    ManyMaxima maxima;
    if (samples.empty()) return maxima;
    const std::size_t bonds = samples.front().gaps.size();
    std::vector<double> t_ref(bonds, 0.0), previous_h(bonds, pair.h0);
    for (const ManySample& sample : samples) {
        const std::vector<double>& velocity = sample.rates.velocity;
        const long long n = static_cast<long long>(velocity.size()) / dimension;
        const double v_scale =
            *std::max_element(velocity.begin(), velocity.end(),
                              [](double left, double right) { return std::abs(left) < std::abs(right); });
        for (int c = 0; c < dimension; ++c) {
            double mean = 0;
            for (long long i = 0; i < n; ++i)
                mean += velocity[i * dimension + c] / n;
            if (v_scale != 0) maxima.mean_velocity = std::max(maxima.mean_velocity, std::abs(mean / v_scale));
        }
        const auto [low, high] = std::minmax_element(sample.gaps.begin(), sample.gaps.end());
        maxima.symmetry_deviation = std::max(maxima.symmetry_deviation, (*high - *low) / *low);
        // Every bond against the pair reference (the same for all bonds by symmetry or statics).
        for (std::size_t bond = 0; bond < bonds; ++bond) {
            const double h = sample.gaps[bond];
            if (h < previous_h[bond]) t_ref[bond] += approach_time_reference(pair, previous_h[bond], h);
            previous_h[bond] = h;
            maxima.pair_reference_error =
                std::max(maxima.pair_reference_error,
                         std::abs(sample.rates.gap_rate[bond]) * std::abs(sample.t - t_ref[bond]) / h);
            maxima.pair_force_residual = std::max(maxima.pair_force_residual,
                                                  std::abs(sample.rates.pair_force[bond] / pair_force - 1.0));
        }
        maxima.linear_system_residual = std::max(maxima.linear_system_residual, sample.rates.residual);
    }
    return maxima;
}

} // namespace softgrain::sd
