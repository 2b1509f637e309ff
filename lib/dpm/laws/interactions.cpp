#include "dpm/laws/interactions.hpp"

#include "dpm/system/contact_list.hpp"
#include "dpm/system/system.hpp"

#include <algorithm>
#include <array>

namespace softgrain::dpm {

namespace {

Eigen::Vector2d point(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

// The spring k/2 (sigma - r)^2 between vertices i and j at local positions r_i and r_j (j's image), adding
// its derivatives. The gradient alone (FIRE) is analytic: dU/dr_j = -k (sigma - r) (r_j - r_i)/r = -dU/dr_i
// (verification/dpm/system/contact_list.cpp checks it against AutoDiff); Hessians and virials come from
// AutoDiff.
// AutoDiff path, out of line so that the analytic path below stays small enough to inline into the contact
// loops (FIRE evaluates it at every contact of every step).
[[gnu::noinline]] double add_vertex_spring_derivatives(const VertexSpringEnergy& spring, int i, int j,
                                                       const Eigen::Vector2d& ri, const Eigen::Vector2d& rj,
                                                       Eigen::VectorXd* gradient, HessianSink hessian,
                                                       Eigen::Matrix2d* virial)
{
    Eigen::Vector4d local;
    local << ri, rj;
    return add_local_term<2, 2>(spring, std::array<int, 2>{i, j}, local, gradient, hessian, virial);
}

double add_vertex_spring(const VertexSpringEnergy& spring, int i, int j, const Eigen::Vector2d& ri,
                         const Eigen::Vector2d& rj, Eigen::VectorXd* gradient, HessianSink hessian,
                         Eigen::Matrix2d* virial)
{
    if (hessian || virial)
        return add_vertex_spring_derivatives(spring, i, j, ri, rj, gradient, hessian, virial);
    const Eigen::Vector2d d = rj - ri;
    const double r = d.norm(), overlap = spring.sigma - r;
    if (gradient) {
        const Eigen::Vector2d towards_j = (-spring.k * overlap / r) * d;
        gradient->segment<2>(2 * j) += towards_j;
        gradient->segment<2>(2 * i) -= towards_j;
    }
    return 0.5 * spring.k * overlap * overlap;
}

// Eq. (9.4) over the listed vertex pairs, each once, in (i, j) order.
double rough_contacts(const DpmSystem& s, const ContactList& list, const Eigen::VectorXd& x,
                      Eigen::VectorXd* gradient, HessianSink hessian, Eigen::Matrix2d* virial)
{
    double energy = 0;
    for (const VertexPair& pair : list.pairs()) {
        const VertexNeighbour& n = pair.neighbour;
        const Eigen::Vector2d ri = point(x, pair.i), rj = point(x, n.j) + n.shift;
        if ((rj - ri).squaredNorm() >= n.sigma * n.sigma) continue; // Theta(sigma - r)
        energy += add_vertex_spring({s.kc, n.sigma}, pair.i, n.j, ri, rj, gradient, hessian, virial);
    }
    return energy;
}

// Eqs. (9.6), (9.8), (9.9) of vertex i (particle a) against particle b, whose vertices are imaged by
// `shift`, with the 1/2 of eq. (9.5) (one ordered pair).
class SmoothVertexParticle
{
  public:
    SmoothVertexParticle(const DpmSystem& s, const Eigen::VectorXd& x, int i, const Particle& b,
                         const Eigen::Vector2d& shift, double sigma, unsigned terms)
        : x_(x), i_(i), b_(b), shift_(shift), sigma_(sigma), terms_(terms),
          p_(point(x, i)), edge_{0.5 * s.kc, sigma}, convex_{0.5 * s.kc, sigma}, concave_{-0.5 * s.kc, sigma}
    {
    }

    // The terms of b's vertex j (local index): U^edge of edge j (from vertex j-1 to vertex j) when
    // `with_edge`, U^concave and U^convex at vertex j when `with_corner`. Order as in the sum of eq. (9.5).
    double add(int j, bool with_edge, bool with_corner, Eigen::VectorXd* gradient, HessianSink hessian,
               Eigen::Matrix2d* virial) const
    {
        const int vj = vertex_of_b(j), previous = vertex_of_b(j - 1), next = vertex_of_b(j + 1);
        const Eigen::Vector2d rj = position(vj), rp = position(previous), rn = position(next);
        double energy = 0;
        // U^edge, eq. (9.6): 0 < d < sigma and vertex i projects inside edge j.
        if (with_edge && (terms_ & edge_smooth)) {
            const double d = distance_to_edge(rp, rj);
            if (d > 0 && d < sigma_ && (p_ - rp).dot(rj - rp) > 0 && (p_ - rj).dot(rp - rj) > 0) {
                Eigen::Matrix<double, 6, 1> local;
                local << p_, rp, rj;
                energy += add_local_term<2, 3>(edge_, std::array<int, 3>{i_, previous, vj}, local, gradient,
                                               hessian, virial);
            }
        }
        if (!with_corner || (p_ - rj).squaredNorm() >= sigma_ * sigma_) return energy; // Theta(sigma - r)
        const double towards_previous = (p_ - rj).dot(rp - rj), towards_next = (p_ - rj).dot(rn - rj);
        // U^concave, eq. (9.8): inside the strips of edges j and j+1 at vertex j and outside both.
        if ((terms_ & concave_smooth) && towards_previous > 0 && towards_next > 0 &&
            distance_to_edge(rp, rj) > 0 && distance_to_edge(rj, rn) > 0)
            energy += add_vertex_spring(concave_, i_, vj, p_, rj, gradient, hessian, virial);
        // U^convex, eq. (9.9): beyond both edges at vertex j.
        if ((terms_ & convex_smooth) && towards_previous < 0 && towards_next < 0)
            energy += add_vertex_spring(convex_, i_, vj, p_, rj, gradient, hessian, virial);
        return energy;
    }

  private:
    int vertex_of_b(int j) const { return b_.first + ((j % b_.count) + b_.count) % b_.count; }
    Eigen::Vector2d position(int v) const { return point(x_, v) + shift_; }
    double distance_to_edge(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const
    {
        Eigen::Matrix<double, 6, 1> local;
        local << p_, from, to;
        return signed_edge_distance(local);
    }

    const Eigen::VectorXd& x_;
    int i_;
    const Particle& b_;
    Eigen::Vector2d shift_;
    double sigma_;
    unsigned terms_;
    Eigen::Vector2d p_;
    VertexEdgeEnergy edge_;
    VertexSpringEnergy convex_, concave_;
};

// Eq. (9.5) over the listed candidates: for each vertex i and each other particle b with candidates near
// i, the edges that end at a candidate and the corners at the candidates, in b's vertex order. Every active
// term has a candidate end (contact_list.hpp), so this is the full sum.
double smooth_contacts(const DpmSystem& s, const ContactList& list, const Eigen::VectorXd& x,
                       Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms,
                       Eigen::Matrix2d* virial)
{
    enum : unsigned char { edge = 1, corner = 2 };
    std::vector<unsigned char> marks;
    std::vector<int> marked;
    double energy = 0;
    for (int i = 0; i < s.vertex_count(); ++i) {
        const std::span<const VertexNeighbour> near = list.neighbours(i);
        for (std::size_t first = 0; first < near.size();) {
            const Particle& b = s.particles[list.particle_of(near[first].j)];
            std::size_t end = first;
            while (end < near.size() && near[end].j < b.first + b.count)
                ++end;
            if (b.count >= 2) { // a disk has no edges
                marks.assign(static_cast<std::size_t>(b.count), 0);
                marked.clear();
                const auto mark = [&](int j, unsigned char what) {
                    if (!marks[j]) marked.push_back(j);
                    marks[j] |= what;
                };
                for (std::size_t k = first; k < end; ++k) {
                    const int j = near[k].j - b.first;
                    mark(j, edge | corner);        // edge j ends at vertex j
                    mark((j + 1) % b.count, edge); // edge j+1 starts there
                }
                std::sort(marked.begin(), marked.end());
                const SmoothVertexParticle pair(s, x, i, b, near[first].shift, near[first].sigma, terms);
                for (const int j : marked)
                    energy += pair.add(j, marks[j] & edge, marks[j] & corner, gradient, hessian, virial);
            }
            first = end;
        }
    }
    return energy;
}

} // namespace

double interaction_energy(const DpmSystem& system, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                          HessianSink hessian, unsigned smooth_terms, Eigen::Matrix2d* virial)
{
    if (system.particles.empty() || system.interaction == InteractionKind::none) return 0;
    const std::shared_ptr<const ContactList> list = system.contacts.list(system, x);
    if (system.interaction == InteractionKind::rough)
        return rough_contacts(system, *list, x, gradient, hessian, virial);
    return smooth_contacts(system, *list, x, gradient, hessian, smooth_terms, virial);
}

} // namespace softgrain::dpm
