#include "dpm/protocols/boundary_jam.hpp"

#include "core/errors.hpp"
#include "core/fire.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace softgrain::dpm {

namespace {

// theta: for the contact graph of 4 disks, the smallest angle at a disk between its two neighbours along a
// 4-cycle of contacts (the parallelogram's smaller interior angle, <= 90 degrees); NaN without a 4-cycle.
double parallelogram_angle(const Eigen::VectorXd& x, const std::vector<std::pair<int, int>>& contacts)
{
    const auto touching = [&](int a, int b) {
        return std::find(contacts.begin(), contacts.end(), std::pair{std::min(a, b), std::max(a, b)}) !=
               contacts.end();
    };
    double best = std::numeric_limits<double>::quiet_NaN();
    const int cycles[3][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}};
    for (const auto& c : cycles) {
        bool closed = true;
        for (int k = 0; k < 4; ++k)
            closed = closed && touching(c[k], c[(k + 1) % 4]);
        if (!closed) continue;
        for (int k = 0; k < 4; ++k) {
            const Eigen::Vector2d p = x.segment<2>(2 * c[k]);
            const Eigen::Vector2d a = x.segment<2>(2 * c[(k + 3) % 4]) - p,
                                  b = x.segment<2>(2 * c[(k + 1) % 4]) - p;
            const double angle = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
            const double smaller = std::min(angle, std::numbers::pi - angle) * 180 / std::numbers::pi;
            if (!(smaller >= best)) best = smaller; // NaN-safe minimum
        }
    }
    return best;
}

// The N-gon inscribed in the ellipse of semi-axes (e r, r) at equal steps of the ellipse's parameter.
Eigen::Matrix2Xd ellipse_polygon(int n, double r, double e)
{
    Eigen::Matrix2Xd v = regular_polygon(n, r, Eigen::Vector2d::Zero(), 0.0);
    v.row(0) *= e;
    return v;
}

// Aspect ratio e >= 1 at which that polygon has the shape parameter A = p^2/(4 pi a) = A0 (section 9.3.1);
// A grows monotonically with e, so bisection on [1, 50] (A(50) ~ 8 exceeds any A0 of interest).
double ellipse_aspect_for(int n, double A0)
{
    const auto A = [n](double e) {
        const Eigen::VectorXd x = ellipse_polygon(n, 1.0, e).reshaped();
        return shape_parameter(particle_perimeter(x, 0, n), particle_area(x, 0, n));
    };
    double low = 1, high = 50;
    if (A(high) < A0) throw InputError("A0 = " + std::to_string(A0) + ": above the largest supported 8");
    for (int k = 0; k < 60; ++k)
        (A(0.5 * (low + high)) < A0 ? low : high) = 0.5 * (low + high);
    return 0.5 * (low + high);
}

} // namespace

Eigen::Matrix2Xd initial_boundary(const BoundaryJamOptions& options)
{
    const double ring_radius = 2.5 + options.boundary_sigma; // [d]
    if (options.ka > 0 && !(options.A0 >= minimum_shape_parameter(options.boundary_nodes)))
        throw InputError("A0 = " + std::to_string(options.A0) + ": below A_min = " +
                         std::to_string(minimum_shape_parameter(options.boundary_nodes)) + " of the ring");
    const double aspect = options.ka > 0 ? ellipse_aspect_for(options.boundary_nodes, options.A0) : 1.0;
    const Eigen::Matrix2Xd ring = ellipse_polygon(options.boundary_nodes, ring_radius, aspect);
    const double edge =
        particle_perimeter(ring.reshaped(), 0, options.boundary_nodes) / options.boundary_nodes;
    if (edge >= options.boundary_sigma)
        throw InputError("boundary_sigma = " + std::to_string(options.boundary_sigma) +
                         (options.ka > 0 ? " at A0 = " + std::to_string(options.A0) : std::string()) +
                         ": ring vertices must overlap their neighbours (edge " + std::to_string(edge) +
                         "); raise boundary_nodes or boundary_sigma, or lower A0");
    return ring;
}

BoundaryJamResult jam_in_boundary(const BoundaryJamOptions& options)
{
    const double pi = std::numbers::pi, d = 1.0, energy_target = 1e-8;
    BoundaryJamResult out;
    DpmSystem& s = out.system;
    s.interaction = InteractionKind::rough;
    Eigen::VectorXd& x = out.x;
    Rng rng(options.seed);
    // Disks at random in a circle of radius 1.5 d, not overlapping; the ring of radius 2.5 d around them.
    std::vector<Eigen::Vector2d> centres;
    while (static_cast<int>(centres.size()) < options.disks) {
        const double r = 1.5 * std::sqrt(rng.uniform()), phi = 2 * pi * rng.uniform();
        const Eigen::Vector2d c(r * std::cos(phi), r * std::sin(phi));
        bool free = true;
        for (const auto& q : centres)
            free = free && (c - q).norm() > d;
        if (free) {
            centres.push_back(c);
            s.add_particle(Eigen::Matrix2Xd(c), d, ShapeParameters{}, x);
        }
    }
    const Eigen::Matrix2Xd ring_vertices = initial_boundary(options);
    ShapeParameters ring;
    ring.kl = options.kl;
    const Eigen::VectorXd ring_x = ring_vertices.reshaped();
    ring.l0 = particle_perimeter(ring_x, 0, options.boundary_nodes) / options.boundary_nodes;
    if (options.ka > 0) { // eq. (9.1) area term with a0 = (N_mu l0)^2/(4 pi A0)
        ring.ka = options.ka;
        ring.a0 = std::pow(options.boundary_nodes * ring.l0, 2) / (4 * pi * options.A0);
    }
    s.add_particle(ring_vertices, options.boundary_sigma, ring, x);

    FireOptions fire;
    // The area term's Hessian is k_a grad(a) grad(a)^T, |grad a|^2 ~ N_mu l0^2 (each vertex moves a by ~l0).
    const double area_stiffness = options.ka * options.boundary_nodes * ring.l0 * ring.l0;
    fire.dt_max = 0.3 / std::sqrt(std::max({4.0, 4 * options.kl, 2 * area_stiffness}));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-3 * std::sqrt(energy_target);
    double step = 1e-2; // relative shrink of l0
    for (int k = 0;; ++k) {
        if (k > 10000 || step < 1e-12)
            throw NumericalError("boundary jamming (energy " + std::to_string(out.energy) + ")", k,
                                 "the bisection on the ring's rest length did not bracket the target");
        const Eigen::VectorXd x_before = x;
        const ShapeParameters shape_before = s.particles.back().shape;
        s.particles.back().shape.l0 *= 1 - step;
        s.particles.back().shape.a0 *= (1 - step) * (1 - step); // A0 unchanged
        const FireResult r = relax_fire(s, x, fire);
        out.iterations += r.iterations;
        if (!r.converged)
            throw NumericalError("relaxation in the boundary (" + fire_shortfall(r, fire) + ")", k,
                                 "time step too large");
        if (r.energy > 2 * energy_target) { // overshoot: undo, halve
            x = x_before;
            s.particles.back().shape = shape_before;
            step *= 0.5;
            continue;
        }
        out.energy = r.energy;
        if (r.energy >= energy_target) break;
    }
    std::vector<std::pair<int, int>> contacts;
    for (int a = 0; a < options.disks; ++a)
        for (int b = a + 1; b < options.disks; ++b)
            if ((x.segment<2>(2 * a) - x.segment<2>(2 * b)).norm() < d) contacts.push_back({a, b});
    out.disk_contacts = static_cast<int>(contacts.size());
    out.theta =
        options.disks == 4 ? parallelogram_angle(x, contacts) : std::numeric_limits<double>::quiet_NaN();
    return out;
}

int count_distinct_packings(const std::map<int, std::vector<double>>& thetas)
{
    int distinct = 0;
    for (const auto& [contacts, list] : thetas) {
        std::vector<double> angles;
        bool without_cycle = false;
        for (double t : list) {
            if (std::isnan(t))
                without_cycle = true;
            else
                angles.push_back(t);
        }
        distinct += without_cycle;
        std::sort(angles.begin(), angles.end());
        for (std::size_t k = 0; k < angles.size(); ++k)
            distinct += k == 0 || angles[k] - angles[k - 1] > 1.0;
    }
    return distinct;
}

double largest_gap_over_range(std::vector<double> angles)
{
    std::erase_if(angles, [](double t) { return std::isnan(t); });
    if (angles.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    std::sort(angles.begin(), angles.end());
    double gap = 0;
    for (std::size_t k = 1; k < angles.size(); ++k)
        gap = std::max(gap, angles[k] - angles[k - 1]);
    return gap / (angles.back() - angles.front());
}

ThetaRange theta_range(const std::vector<double>& thetas)
{
    ThetaRange range;
    for (const double theta : thetas) {
        if (std::isnan(theta)) continue;
        ++range.packings;
        range.min = std::min(range.min.value_or(theta), theta);
        range.max = std::max(range.max.value_or(theta), theta);
    }
    return range;
}

} // namespace softgrain::dpm
