#include "dpm/analysis/packing_fraction.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::dpm {

double vertex_overlap_segment(double r, double sigma_mu, double sigma_beta)
{
    const double a = 0.5 * sigma_mu, b = 0.5 * sigma_beta;
    if (r >= a + b) return 0.0;
    const double d = (r * r - b * b + a * a) / (2 * r); // distance from the centre of mu to the radical line
    // |d| <= a in the regime of eq. (9.20); beyond it (one disk nested in the other) the radical line misses
    // disk mu and the segment is all of it (d <= -a) or nothing (d >= a): clamping d gives exactly that.
    const double c = std::clamp(d / a, -1.0, 1.0);
    return a * a * (std::acos(c) - c * std::sqrt(1 - c * c));
}

namespace {

Eigen::Vector2d vertex_position(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

int wrap(int i, int n)
{
    return ((i % n) + n) % n;
}

// Crossing-number test of a point against a polygon given as a 2 x n matrix.
bool inside_polygon(const Eigen::Vector2d& p, const Eigen::Matrix2Xd& v)
{
    bool inside = false;
    const Eigen::Index n = v.cols();
    for (Eigen::Index i = 0, j = n - 1; i < n; j = i++) {
        if ((v(1, i) > p.y()) != (v(1, j) > p.y()) &&
            p.x() < (v(0, j) - v(0, i)) * (p.y() - v(1, i)) / (v(1, j) - v(1, i)) + v(0, i))
            inside = !inside;
    }
    return inside;
}

} // namespace

std::vector<PackingAreas> particle_area_terms(const DpmSystem& system, const Eigen::VectorXd& x)
{
    if (!system.box) throw InputError("packing fraction: the system has no periodic box");
    const double pi = std::numbers::pi;
    std::vector<PackingAreas> terms(system.particles.size());
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Particle& p = system.particles[m];
        PackingAreas& t = terms[m];
        t.polygon = particle_area(x, p.first, p.count);
        t.vertices = p.count * pi * p.sigma * p.sigma / 4;
        for (int i = 0; i < p.count; ++i) {
            const Eigen::Vector2d prev = vertex_position(x, p.first + wrap(i - 1, p.count));
            const Eigen::Vector2d here = vertex_position(x, p.first + i);
            const Eigen::Vector2d next = vertex_position(x, p.first + wrap(i + 1, p.count));
            const Eigen::Vector2d in = here - prev, out = next - here;
            const double theta =
                std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)); // turning angle
            t.sector += p.sigma * p.sigma * (pi - theta) / 8;
            t.pair += vertex_overlap_segment(out.norm(), p.sigma, p.sigma); // I_{mu i, mu(i+1)}
        }
    }
    // Interparticle overlaps, each segment attributed to its own vertex (minimum image).
    for (const VertexContact& c : vertex_contacts(system, x)) {
        const double sigma_a = system.particles[c.a].sigma, sigma_b = system.particles[c.b].sigma;
        const double r = c.r.norm();
        terms[c.a].pair += vertex_overlap_segment(r, sigma_a, sigma_b);
        terms[c.b].pair += vertex_overlap_segment(r, sigma_b, sigma_a);
    }
    for (PackingAreas& t : terms)
        t.phi = t.polygon + t.vertices - t.sector - t.pair; // A_mu, eq. (9.21)
    return terms;
}

std::vector<double> particle_areas(const DpmSystem& system, const Eigen::VectorXd& x)
{
    std::vector<double> areas;
    for (const PackingAreas& t : particle_area_terms(system, x))
        areas.push_back(t.phi);
    return areas;
}

PackingAreas packing_areas_analytic(const DpmSystem& system, const Eigen::VectorXd& x)
{
    PackingAreas a;
    for (const PackingAreas& t : particle_area_terms(system, x)) {
        a.polygon += t.polygon;
        a.vertices += t.vertices;
        a.sector += t.sector;
        a.pair += t.pair;
        a.phi += t.phi; // A_particles = sum_mu A_mu, eq. (9.18)
    }
    const double box_area = system.box->prod(); // eq. (9.22)
    a.polygon /= box_area;
    a.vertices /= box_area;
    a.sector /= box_area;
    a.pair /= box_area;
    a.phi /= box_area;
    return a;
}

PackingAreasEstimate packing_areas_monte_carlo(const DpmSystem& system, const Eigen::VectorXd& x,
                                               long samples, std::uint64_t seed)
{
    if (!system.box) throw InputError("packing fraction: the system has no periodic box");
    const Eigen::Vector2d L = *system.box;
    std::vector<Eigen::Matrix2Xd> polygons;
    std::vector<Eigen::Vector2d> centres;
    for (const Particle& p : system.particles) {
        polygons.push_back(x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count));
        centres.push_back(polygons.back().rowwise().mean());
    }
    Rng rng(seed);
    // Running sums of each per-point indicator and of its square.
    Eigen::Array<double, 5, 1> sum = Eigen::Array<double, 5, 1>::Zero(), sum2 = sum;
    for (long k = 0; k < samples; ++k) {
        const Eigen::Vector2d q(rng.uniform(0, L.x()), rng.uniform(0, L.y()));
        double in_polygon = 0, disks = 0, sectors = 0;
        for (std::size_t m = 0; m < polygons.size(); ++m) {
            const Particle& p = system.particles[m];
            const Eigen::Vector2d image = centres[m] + system.image(q - centres[m]); // q near particle m
            const bool own = inside_polygon(image, polygons[m]);
            in_polygon += own;
            for (int i = 0; i < p.count; ++i)
                if ((image - polygons[m].col(i)).squaredNorm() < 0.25 * p.sigma * p.sigma) {
                    disks += 1;
                    sectors += own;
                }
        }
        const double in_union = (in_polygon > 0 || disks > 0) ? 1.0 : 0.0;
        const Eigen::Array<double, 5, 1> values(in_polygon, disks, sectors,
                                                in_polygon + disks - sectors - in_union, in_union);
        sum += values;
        sum2 += values * values;
    }
    const double n = static_cast<double>(samples);
    const Eigen::Array<double, 5, 1> mean = sum / n;
    const Eigen::Array<double, 5, 1> error = ((sum2 / n - mean * mean).max(0.0) / (n - 1)).sqrt();
    PackingAreasEstimate e;
    e.value = {mean(0), mean(1), mean(2), mean(3), mean(4)};
    e.error = {error(0), error(1), error(2), error(3), error(4)};
    return e;
}

} // namespace softgrain::dpm
