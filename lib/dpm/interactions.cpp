#include "dpm/interactions.hpp"

#include "dpm/system.hpp"

namespace softgrain::dpm {

namespace {

Eigen::Vector2d point(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

// Axis-aligned bounding boxes of two particles, grown by the interaction range, overlap.
bool may_touch(const Particle& a, const Particle& b, const Eigen::VectorXd& x)
{
    const auto va = x.segment(2 * a.first, 2 * a.count).reshaped(2, a.count);
    const auto vb = x.segment(2 * b.first, 2 * b.count).reshaped(2, b.count);
    const double range = 0.5 * (a.sigma + b.sigma);
    const Eigen::Array2d gap1 = vb.rowwise().minCoeff().array() - va.rowwise().maxCoeff().array();
    const Eigen::Array2d gap2 = va.rowwise().minCoeff().array() - vb.rowwise().maxCoeff().array();
    return (gap1 < range).all() && (gap2 < range).all();
}

// Eq. (9.4) for every vertex pair of particles a and b.
double rough_pair(const DpmSystem& s, const Particle& a, const Particle& b, const Eigen::VectorXd& x,
                  Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian)
{
    const double sigma = 0.5 * (a.sigma + b.sigma);
    const VertexSpringEnergy spring{s.kc, sigma};
    double energy = 0;
    for (int i = a.first; i < a.first + a.count; ++i)
        for (int j = b.first; j < b.first + b.count; ++j) {
            if ((point(x, j) - point(x, i)).squaredNorm() >= sigma * sigma) continue; // Theta(sigma - r)
            const std::array<int, 2> pair{i, j};
            energy += add_local_term<2, 2>(spring, pair, gather<2, 2>(x, pair), gradient, hessian);
        }
    return energy;
}

// Eqs. (9.6), (9.8), (9.9) for every vertex i of particle a against particle b (one ordered pair), with
// the 1/2 of eq. (9.5).
double smooth_vertex_particle(const DpmSystem& s, const Particle& a, const Particle& b,
                              const Eigen::VectorXd& x, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian,
                              unsigned terms)
{
    if (b.count < 2) return 0; // a disk has no edges
    const double sigma = 0.5 * (a.sigma + b.sigma);
    const double k = 0.5 * s.kc; // the 1/2 of eq. (9.5)
    const VertexEdgeEnergy edge{k, sigma};
    const VertexSpringEnergy convex{k, sigma}, concave{-k, sigma};
    const auto vertex_of_b = [&](int j) { return b.first + ((j % b.count) + b.count) % b.count; };
    const auto distance_to_edge = [&](const Eigen::Vector2d& p, int j) { // d from edge j: (j-1) -> j
        Eigen::Matrix<double, 6, 1> local;
        local << p, point(x, vertex_of_b(j - 1)), point(x, vertex_of_b(j));
        return signed_edge_distance(local);
    };
    double energy = 0;
    for (int i = a.first; i < a.first + a.count; ++i) {
        const Eigen::Vector2d p = point(x, i);
        for (int j = 0; j < b.count; ++j) {
            const int vj = vertex_of_b(j), previous = vertex_of_b(j - 1), next = vertex_of_b(j + 1);
            const Eigen::Vector2d rj = point(x, vj), rp = point(x, previous), rn = point(x, next);
            // U^edge, eq. (9.6), edge j from vertex j-1 to vertex j.
            if (terms & edge_smooth) {
                const double d = distance_to_edge(p, j);
                if (d > 0 && d < sigma && (p - rp).dot(rj - rp) > 0 && (p - rj).dot(rp - rj) > 0) {
                    const std::array<int, 3> triple{i, previous, vj};
                    energy += add_local_term<2, 3>(edge, triple, gather<2, 3>(x, triple), gradient, hessian);
                }
            }
            const double r2 = (p - rj).squaredNorm();
            if (r2 >= sigma * sigma) continue; // Theta(sigma - r) of eqs. (9.8), (9.9)
            const std::array<int, 2> pair{i, vj};
            const double towards_previous = (p - rj).dot(rp - rj), towards_next = (p - rj).dot(rn - rj);
            // U^concave, eq. (9.8): inside the strips of edges j and j+1 at vertex j and outside both.
            if ((terms & concave_smooth) && towards_previous > 0 && towards_next > 0 &&
                distance_to_edge(p, j) > 0 && distance_to_edge(p, j + 1) > 0)
                energy += add_local_term<2, 2>(concave, pair, gather<2, 2>(x, pair), gradient, hessian);
            // U^convex, eq. (9.9): beyond both edges at vertex j.
            if ((terms & convex_smooth) && towards_previous < 0 && towards_next < 0)
                energy += add_local_term<2, 2>(convex, pair, gather<2, 2>(x, pair), gradient, hessian);
        }
    }
    return energy;
}

} // namespace

double interaction_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                          Eigen::MatrixXd* hessian, unsigned smooth_terms)
{
    double energy = 0;
    const auto& particles = system.particles;
    for (std::size_t m = 0; m < particles.size(); ++m)
        for (std::size_t b = m + 1; b < particles.size(); ++b) {
            if (!may_touch(particles[m], particles[b], x)) continue;
            if (system.interaction == InteractionKind::rough)
                energy += rough_pair(system, particles[m], particles[b], x, gradient, hessian);
            else if (system.interaction == InteractionKind::smooth)
                energy += smooth_vertex_particle(system, particles[m], particles[b], x, gradient, hessian,
                                                 smooth_terms) +
                          smooth_vertex_particle(system, particles[b], particles[m], x, gradient, hessian,
                                                 smooth_terms);
        }
    return energy;
}

} // namespace softgrain::dpm
