#include "dpm/interactions.hpp"

#include "dpm/system.hpp"

#include "core/errors.hpp"
#include "core/neighbour_list.hpp"

#include <algorithm>
#include <string>

namespace softgrain::dpm {

namespace {

Eigen::Vector2d point(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

// Centre (vertex mean) and radius of a circle around a particle's vertices.
std::pair<Eigen::Vector2d, double> bounding_circle(const Particle& p, const Eigen::VectorXd& x)
{
    const auto v = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count);
    const Eigen::Vector2d centre = v.rowwise().mean();
    return {centre, (v.colwise() - centre).colwise().norm().maxCoeff()};
}

// The translation that brings particle b to its image closest to particle a (zero without a box).
Eigen::Vector2d image_shift(const DpmSystem& s, const Eigen::Vector2d& ca, const Eigen::Vector2d& cb)
{
    const Eigen::Vector2d d = cb - ca;
    return s.image(d) - d;
}

// Local coordinates of `points`, with `shift` added to those of particle b (periodic image).
template <int K>
Eigen::Matrix<double, 2 * K, 1> gather_image(const Eigen::VectorXd& x, const std::array<int, K>& points,
                                             const Particle& b, const Eigen::Vector2d& shift)
{
    Eigen::Matrix<double, 2 * K, 1> local = gather<2, K>(x, points);
    for (int k = 0; k < K; ++k)
        if (points[k] >= b.first && points[k] < b.first + b.count) local.template segment<2>(2 * k) += shift;
    return local;
}

// Eq. (9.4) for every vertex pair of particles a and b.
double rough_pair(const DpmSystem& s, const Particle& a, const Particle& b, const Eigen::Vector2d& shift,
                  const Eigen::VectorXd& x, Eigen::VectorXd* gradient, HessianSink hessian,
                  Eigen::Matrix2d* virial)
{
    const double sigma = 0.5 * (a.sigma + b.sigma);
    const VertexSpringEnergy spring{s.kc, sigma};
    double energy = 0;
    for (int i = a.first; i < a.first + a.count; ++i)
        for (int j = b.first; j < b.first + b.count; ++j) {
            if ((point(x, j) + shift - point(x, i)).squaredNorm() >= sigma * sigma)
                continue; // Theta(sigma - r)
            const std::array<int, 2> pair{i, j};
            energy += add_local_term<2, 2>(spring, pair, gather_image<2>(x, pair, b, shift), gradient,
                                           hessian, virial);
        }
    return energy;
}

// Eqs. (9.6), (9.8), (9.9) for every vertex i of particle a against particle b (one ordered pair), with
// the 1/2 of eq. (9.5).
double smooth_vertex_particle(const DpmSystem& s, const Particle& a, const Particle& b,
                              const Eigen::Vector2d& shift, const Eigen::VectorXd& x,
                              Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms,
                              Eigen::Matrix2d* virial)
{
    if (b.count < 2) return 0; // a disk has no edges
    const double sigma = 0.5 * (a.sigma + b.sigma);
    const double k = 0.5 * s.kc; // the 1/2 of eq. (9.5)
    const VertexEdgeEnergy edge{k, sigma};
    const VertexSpringEnergy convex{k, sigma}, concave{-k, sigma};
    const auto vertex_of_b = [&](int j) { return b.first + ((j % b.count) + b.count) % b.count; };
    const auto pos = [&](int v) { return Eigen::Vector2d(point(x, v) + shift); }; // b's vertices, imaged
    const auto distance_to_edge = [&](const Eigen::Vector2d& p, int j) {          // d from edge j: (j-1) -> j
        Eigen::Matrix<double, 6, 1> local;
        local << p, pos(vertex_of_b(j - 1)), pos(vertex_of_b(j));
        return signed_edge_distance(local);
    };
    double energy = 0;
    for (int i = a.first; i < a.first + a.count; ++i) {
        const Eigen::Vector2d p = point(x, i);
        for (int j = 0; j < b.count; ++j) {
            const int vj = vertex_of_b(j), previous = vertex_of_b(j - 1), next = vertex_of_b(j + 1);
            const Eigen::Vector2d rj = pos(vj), rp = pos(previous), rn = pos(next);
            // U^edge, eq. (9.6), edge j from vertex j-1 to vertex j.
            if (terms & edge_smooth) {
                const double d = distance_to_edge(p, j);
                if (d > 0 && d < sigma && (p - rp).dot(rj - rp) > 0 && (p - rj).dot(rp - rj) > 0) {
                    const std::array<int, 3> triple{i, previous, vj};
                    energy += add_local_term<2, 3>(edge, triple, gather_image<3>(x, triple, b, shift),
                                                   gradient, hessian, virial);
                }
            }
            const double r2 = (p - rj).squaredNorm();
            if (r2 >= sigma * sigma) continue; // Theta(sigma - r) of eqs. (9.8), (9.9)
            const std::array<int, 2> pair{i, vj};
            const double towards_previous = (p - rj).dot(rp - rj), towards_next = (p - rj).dot(rn - rj);
            // U^concave, eq. (9.8): inside the strips of edges j and j+1 at vertex j and outside both.
            if ((terms & concave_smooth) && towards_previous > 0 && towards_next > 0 &&
                distance_to_edge(p, j) > 0 && distance_to_edge(p, j + 1) > 0)
                energy += add_local_term<2, 2>(concave, pair, gather_image<2>(x, pair, b, shift), gradient,
                                               hessian, virial);
            // U^convex, eq. (9.9): beyond both edges at vertex j.
            if ((terms & convex_smooth) && towards_previous < 0 && towards_next < 0)
                energy += add_local_term<2, 2>(convex, pair, gather_image<2>(x, pair, b, shift), gradient,
                                               hessian, virial);
        }
    }
    return energy;
}

} // namespace

double interaction_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                          HessianSink hessian, unsigned smooth_terms, Eigen::Matrix2d* virial)
{
    double energy = 0;
    const auto& particles = system.particles;
    std::vector<std::pair<Eigen::Vector2d, double>> circles;
    double largest_reach = 0;
    for (const Particle& p : particles) {
        circles.push_back(bounding_circle(p, x));
        largest_reach = std::max(largest_reach, 2 * circles.back().second + p.sigma);
    }
    // One image per particle pair is exact only if no particle can touch two images of another.
    if (system.box && 2 * largest_reach >= system.box->minCoeff())
        throw NumericalError("periodic box side " + std::to_string(system.box->minCoeff()) +
                                 " below twice the largest pair reach " + std::to_string(largest_reach),
                             0, "too few particles for the box; use more particles");
    const auto interact = [&](std::size_t m, std::size_t b) {
        const Particle &pm = particles[m], &pb = particles[b];
        const Eigen::Vector2d shift = image_shift(system, circles[m].first, circles[b].first);
        const double reach = circles[m].second + circles[b].second + 0.5 * (pm.sigma + pb.sigma);
        if ((circles[b].first + shift - circles[m].first).squaredNorm() >= reach * reach) return;
        if (system.interaction == InteractionKind::rough)
            energy += rough_pair(system, pm, pb, shift, x, gradient, hessian, virial);
        else if (system.interaction == InteractionKind::smooth)
            energy +=
                smooth_vertex_particle(system, pm, pb, shift, x, gradient, hessian, smooth_terms, virial) +
                smooth_vertex_particle(system, pb, pm, -shift, x, gradient, hessian, smooth_terms, virial);
    };
    if (system.cell_list && system.lees_edwards_strain == 0 && !particles.empty()) {
        // Every pair within reach is closer than the largest reach: the list holds them all, sorted (m < b)
        // as the all-pairs loop visits them.
        Points<2> centres(2, particles.size());
        for (std::size_t m = 0; m < particles.size(); ++m)
            centres.col(m) = circles[m].first;
        NeighbourList<2> list(largest_reach, 0.0, system.box);
        list.update(centres);
        for (const auto& [m, b] : list.pairs())
            interact(m, b);
    } else {
        for (std::size_t m = 0; m < particles.size(); ++m)
            for (std::size_t b = m + 1; b < particles.size(); ++b)
                interact(m, b);
    }
    return energy;
}

} // namespace softgrain::dpm
